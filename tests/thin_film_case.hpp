// SPDX-License-Identifier: MIT
// A thin drying film for engine tests on a small cell: 36 x 36 um, 2.5 mg/cm2, one 3 um NCM
// class, with its recipe, scaled parameters and level schedule (checkpoint and MPI tests).
#pragma once
#include "drydem/drying/derived_checks.hpp"
#include "drydem/drying/liquid_level.hpp"
#include "drydem/drying/scaling.hpp"
#include "drydem/setup/formulation.hpp"

namespace drydem::test {

struct Case {
    Config c;
    FilmRecipe recipe;
    ScaledParameters scaled;
    LiquidLevelSchedule schedule;
};

inline Case thin_film() {
    Config c = load_config("", "t",
                           {"film.box_x=36um", "film.box_y=36um", "film.areal_loading=2.5mg/cm^2",
                            "formulation.ncm_diameters=[\"3 um\"]"});
    FilmRecipe r = make_recipe(c);
    ScaledParameters s = scale_parameters(c);
    LiquidLevelSchedule l{r.wet_film_height, s.level_speeds_scaled, s.zone_duration_scaled};
    return {c, r, s, l};
}

} // namespace drydem::test
