// SPDX-License-Identifier: MIT
// The valid range of a law's parameters, declared by the law beside its Params (issue 33): every
// pair and body law lists each parameter it reads with the interval it must lie in, and the
// force field is refused when a value, as simulated, falls outside or is not finite. A value
// that only passed the configuration's own checks because two keys met in a product (a factor
// of 1e308 on a Hamaker constant) is caught here, with the law and the parameter named.
#pragma once
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace drydem {

/// One parameter's interval: lo < or ≤ value < or ≤ hi, and always finite.
template <class P>
struct ParamLimit {
    std::string_view name; ///< the field, as in the law's Params
    double P::*field;
    double lo = 0.0, hi = INFINITY;
    bool lo_open = false, hi_open = false; ///< true: the bound itself is excluded

    [[nodiscard]] bool admits(double v) const {
        if (!std::isfinite(v)) return false;
        const bool above = lo_open ? v > lo : v >= lo;
        const bool below = hi_open ? v < hi : v <= hi;
        return above && below;
    }
    [[nodiscard]] std::string interval() const {
        auto num = [](double x) {
            if (std::isinf(x)) return std::string(x > 0 ? "inf" : "-inf");
            char b[32];
            std::snprintf(b, sizeof b, "%g", x);
            return std::string(b);
        };
        return std::string(lo_open ? "(" : "[") + num(lo) + ", " + num(hi) +
               (hi_open || std::isinf(hi) ? ")" : "]");
    }
};

/// Every parameter of law L's `p` outside its declared interval, as "name = value, allowed I".
template <class L>
std::vector<std::string> limit_violations(const typename L::Params& p) {
    std::vector<std::string> out;
    for (const auto& l : L::limits)
        if (!l.admits(p.*(l.field))) {
            char b[32];
            std::snprintf(b, sizeof b, "%g", p.*(l.field));
            out.push_back(std::string(l.name) + " = " + b + ", allowed " + l.interval());
        }
    return out;
}

} // namespace drydem
