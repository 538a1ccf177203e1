// SPDX-License-Identifier: MIT
#include "drydem/drying/derived_checks.hpp"
#include "drydem/study/calibration.hpp"
#include "drydem/study/study.hpp"
#include "drydem/core/error.hpp"
#include "drydem/io/units.hpp"
#include <fmt/format.h>
#include <algorithm>
#include <set>

namespace drydem {

int calibration_initial_points(const Config& c) {
    const int n = c.calibration_initial_points > 0
                      ? c.calibration_initial_points
                      : std::max(4, 2 * int(c.calibration_parameters.size()));
    return std::min(n, c.calibration_evaluations);
}

std::vector<std::string> check_calibration(const Config& c) {
    std::vector<std::string> warnings;
    const auto& ps = c.calibration_parameters;
    if (ps.empty())
        throw InputError(
            "config key 'calibration.parameters': none given; drydem calibrate needs at least one "
            "[[calibration.parameters]] table (key, min, max), e.g. key = \"contact.friction\", "
            "min = 0.4, max = 1.2");
    if (c.calibration_targets.empty())
        throw InputError(
            "config key 'calibration.targets': none given; drydem calibrate needs at least one "
            "[[calibration.targets]] table (quantity, value, uncertainty), e.g. quantity = "
            "\"final_thickness\", value = \"83.8 um\", uncertainty = \"2 um\"");
    const int init = calibration_initial_points(c);
    if (init < 2)
        throw InputError(fmt::format(
            "config keys 'calibration.initial_points' / 'calibration.evaluations': {} "
            "initial point(s); allowed: at least 2 (the surrogate needs two evaluations)",
            init));
    std::set<std::string> quantities;
    for (const auto& t : c.calibration_targets) quantities.insert(calibration_target_name(t));
    if (quantities.size() < ps.size())
        warnings.push_back(fmt::format("{} independent target(s) for {} parameters: the parameters "
                                       "are not all determined (a valley "
                                       "of equally good fits; the reported ranges show it)",
                                       quantities.size(), ps.size()));
    if (quantities.size() < c.calibration_targets.size())
        warnings.push_back(
            "a target quantity is given more than once; its values count as separate measurements");
    const std::string base = to_toml(c);
    for (std::size_t i = 0; i < ps.size(); ++i) {
        for (const double v : {ps[i].min, ps[i].max}) {
            try {
                (void)load_config(base, "<calibration bound>",
                                  {fmt::format("{}={:.17g}", ps[i].key, v)});
            } catch (const InputError& e) {
                throw InputError(fmt::format(
                    "config key 'calibration.parameters[{}]': {} = {:g} ({}) makes the run "
                    "configuration invalid: {}",
                    i + 1, ps[i].key, v, v == ps[i].min ? "min" : "max", e.what()));
            }
        }
    }
    return warnings;
}

nlohmann::json calibration_spec(const Config& c, const std::string& drydem_executable) {
    nlohmann::json j;
    j["format"] = 1;
    j["drydem"] = drydem_executable;
    j["name"] = c.name;
    j["base_seed"] = c.seed;
    j["seeds"] = c.calibration_seeds;
    j["initial_points"] = calibration_initial_points(c);
    j["evaluations"] = c.calibration_evaluations;
    j["sampler"] = c.calibration_sampler;
    j["parameters"] = nlohmann::json::array();
    for (const auto& p : c.calibration_parameters)
        j["parameters"].push_back({{"key", p.key}, {"min", p.min}, {"max", p.max}, {"log", p.log}});
    j["targets"] = nlohmann::json::array();
    for (const auto& t : c.calibration_targets) {
        const auto& qs = calibration_quantities();
        const auto q = std::find_if(qs.begin(), qs.end(), [&](const CalibrationQuantity& x) {
            return x.name == t.quantity;
        });
        nlohmann::json target = {{"quantity", t.quantity},
                                 {"summary_key", std::string(q->summary_key)},
                                 {"unit", std::string(q->unit)},
                                 {"value", t.value / q->si_per_unit},
                                 {"uncertainty", t.uncertainty / q->si_per_unit}};
        if (t.at >=
            0.0) { // a point of a curve (absent otherwise, so older ledgers resume unchanged)
            target["name"] = calibration_target_name(t);
            target["at_s"] = t.at;
        }
        j["targets"].push_back(target);
    }
    j["scheduler"] = scheduler_settings(c);
    return j;
}

} // namespace drydem
