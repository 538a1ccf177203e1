// SPDX-License-Identifier: MIT
// Conformance of every law in BodyLaws to the contract of forces/body_law.hpp, through each law's
// own add_force, so that a body law added later is checked by adding it to the list: for the
// drying film's largest NCM and its CB with every law switched on, at heights in overlap with
// the substrate, in the substrate's lubrication range, at the liquid level's floating
// equilibrium and far from both,
//   - in-plane invariance: the substrate and the liquid are the same everywhere in x and y, so
//     shifting the particle in x, y changes no force (the bodies' analogue of a pair's rigid-body
//     invariance; their reaction is on a fixed body, so there is no third law to check);
//   - the dissipative part of add_force is resistance() applied to the velocities, and the
//     resistance add_force reports is resistance();
//   - stiffness() is -dF/dz of the conservative part (central differences) where it declares one,
//     and a law that declares none has no slope; the sliding spring by one history step;
//   - every declared parameter interval refuses a value outside it, NaN and infinity.
// A toy law (a spring that tethers the particle to a height) composed into a list of its own
// passes the same walk: a new body law needs its header and one list entry.
#include "drydem/drying/law_parameters.hpp"
#include "drydem/forces/force_field.hpp"
#include <gtest/gtest.h>
#include <cmath>
#include <string>
#include <tuple>
#include <utility>

namespace {
using namespace drydem;

struct Particle {
    std::string name;
    double r, m, density;
};

/// Where the liquid level and the calendering plate stand.
struct Surfaces {
    double level;
    double plate = INFINITY;
};

struct Film {
    std::vector<Particle> particles;
    std::vector<BodyParams> params;
    double level;
};

/// The film's largest NCM and CB with their body laws as the drying run makes them (or, with
/// `calendering`, as the calendering run does: the plate on, no liquid).
Film film(bool calendering = false) {
    Config c;
    const FilmRecipe rec = make_recipe(c);
    const ForceField ff = calendering ? make_calendering_force_field(c, rec)
                                      : make_drying_force_field(c, rec, scale_parameters(c));
    Film f;
    for (int s : {rec.cb_species() - 1, rec.cb_species()}) {
        const SizeClass& k = rec.species[std::size_t(s)];
        const double r = 0.5 * k.diameter;
        f.particles.push_back({k.is_cb ? "CB" : "NCM", r, sphere_volume(r) * k.density, k.density});
        f.params.push_back(ff.body_params(s));
    }
    f.level = 40e-6;
    return f;
}

template <class List, class L>
BodyForce force_of(const typename List::Params& p, const Particle& q, const Surfaces& level,
                   const Vec3& x, const Vec3& v = {}, const Vec3& w = {}, double dt = 0.0,
                   BodyResistance* r = nullptr) {
    typename L::State s{};
    BodyForce f{};
    L::add_force({x, v, w, q.r, q.m, q.density, level.level, 0.0, level.plate},
                 List::template params<L>(p), s, dt, f, r);
    return f;
}

void expect_close(const Vec3& a, const Vec3& b, double tol, const std::string& what) {
    EXPECT_LE(norm(a - b), tol) << what << ": (" << a.x << ", " << a.y << ", " << a.z << ") vs ("
                                << b.x << ", " << b.y << ", " << b.z << ")";
}

template <class List, class L>
void check_law(const typename List::Params& p, const Particle& q, const Surfaces& level, double z) {
    const std::string where =
        std::string(L::name) + ", " + q.name + ", z/r " + std::to_string(z / q.r);
    const auto& lp = List::template params<L>(p);
    const Vec3 x{3e-6, 5e-6, z};
    const Vec3 v{1e-4, -2e-4, 3e-4}, w{30.0, -50.0, 20.0}; // small: the contact sticks
    const BodyForce rest = force_of<List, L>(p, q, level, x),
                    moving = force_of<List, L>(p, q, level, x, v, w);
    const double scale = std::max({norm(rest.force), norm(moving.force), 1e-30});
    const double tol = 1e-9 * scale;

    // In-plane invariance.
    const BodyForce shifted = force_of<List, L>(p, q, level, x + Vec3{7e-6, -11e-6, 0.0}, v, w);
    expect_close(shifted.force, moving.force, tol, where + " shifted force");
    expect_close(shifted.torque, moving.torque, tol * q.r, where + " shifted torque");

    // The dissipative part is resistance() on the velocities, and add_force reports it.
    const BodyResistance r =
        L::resistance({x, {}, {}, q.r, q.m, q.density, level.level, 0.0, level.plate}, lp);
    BodyResistance reported{};
    (void)force_of<List, L>(p, q, level, x, v, w, 0.0, &reported);
    EXPECT_NEAR(reported.normal, r.normal, 1e-12 * r.normal) << where;
    EXPECT_NEAR(reported.tangential, r.tangential, 1e-12 * r.tangential) << where;
    EXPECT_NEAR(reported.coupling, r.coupling, 1e-12 * std::abs(r.coupling) + 1e-300) << where;
    const BodyForce dissipative = resistance_force(r, v, w);
    expect_close(moving.force - rest.force, dissipative.force, tol, where + " dissipative force");
    expect_close(moving.torque - rest.torque, dissipative.torque, tol * q.r,
                 where + " dissipative torque");

    // Stiffness: -dF_z/dz by central differences, where the law declares one; none elsewhere.
    const BodyResistance k =
        L::stiffness({x, {}, {}, q.r, q.m, q.density, level.level, 0.0, level.plate}, lp);
    const double h = 1e-6 * q.r;
    const double dfdz = (force_of<List, L>(p, q, level, x + Vec3{0, 0, h}).force.z -
                         force_of<List, L>(p, q, level, x - Vec3{0, 0, h}).force.z) /
                        (2 * h);
    const double noise = 1e-9 * norm(rest.force) / h + 1e-12;
    EXPECT_NEAR(k.normal, -dfdz, 1e-5 * std::abs(dfdz) + noise) << where << " normal stiffness";
    // The sliding spring: one step of the history at a tangential velocity.
    const double dt = 1e-12, u = 1e-4;
    const BodyForce stepped = force_of<List, L>(p, q, level, x, {u, 0, 0}, {}, dt),
                    unstepped = force_of<List, L>(p, q, level, x, {u, 0, 0});
    const double spring = -(stepped.force.x - unstepped.force.x) / (u * dt);
    EXPECT_NEAR(k.tangential, spring, 1e-6 * std::abs(k.tangential) + 1e-9)
        << where << " sliding stiffness";
}

template <class L>
void check_limits(const typename L::Params& valid) {
    EXPECT_TRUE(limit_violations<L>(valid).empty()) << L::name;
    for (const auto& l : L::limits) {
        const double outside[] = {NAN, INFINITY, -INFINITY, l.lo_open ? l.lo : l.lo - 1.0,
                                  l.hi_open ? l.hi : l.hi + 1.0};
        for (double bad : outside) {
            typename L::Params p = valid;
            p.*(l.field) = bad;
            const auto v = limit_violations<L>(p);
            ASSERT_EQ(v.size(), 1u) << L::name << "." << l.name << " = " << bad;
            EXPECT_NE(v[0].find(std::string(l.name)), std::string::npos) << v[0];
        }
    }
}

template <class List, std::size_t... K>
void check_every_law(const typename List::Params& p, const Particle& q, const Surfaces& level,
                     double z, std::index_sequence<K...>) {
    (check_law<List, std::tuple_element_t<K, typename List::Laws>>(p, q, level, z), ...);
}
template <class List, std::size_t... K>
void check_every_limit(const typename List::Params& p, std::index_sequence<K...>) {
    (check_limits<std::tuple_element_t<K, typename List::Laws>>(
         List::template params<std::tuple_element_t<K, typename List::Laws>>(p)),
     ...);
}

template <class List>
void walk(const typename List::Params& p, const Particle& q, const Surfaces& level,
          std::initializer_list<double> heights) {
    constexpr auto all = std::make_index_sequence<std::tuple_size_v<typename List::Laws>>{};
    for (double z : heights) check_every_law<List>(p, q, level, z, all);
    check_every_limit<List>(p, all);
}

TEST(BodyLawConformance, EveryLawOfTheListKeepsTheContract) {
    const Film f = film();
    for (std::size_t k = 0; k < f.particles.size(); ++k) {
        const Particle& q = f.particles[k];
        const double theta = law<CapillaryFrontLaw>(f.params[k]).contact_angle;
        // In overlap with the substrate, in its lubrication range, floating in the level
        // (u = cos θ), and far from both.
        walk<BodyLaws>(f.params[k], q, {f.level},
                       {0.98 * q.r, 1.3 * q.r, f.level - q.r * std::cos(theta), 0.5 * f.level});
    }
}

TEST(BodyLawConformance, TheCalenderingPlateKeepsTheContract) {
    const Film f = film(true);
    const double plate = 40e-6;
    for (std::size_t k = 0; k < f.particles.size(); ++k) {
        const Particle& q = f.particles[k];
        EXPECT_GT(law<PlateContactLaw>(f.params[k]).e_star, 0.0);
        // Below the NCM contacts' yield (δ_y = 1.7 % of r against a wall): in overlap with the
        // substrate, with the plate, and between the two.
        walk<BodyLaws>(f.params[k], q, {-1.0, plate},
                       {0.99 * q.r, plate - 0.99 * q.r, 0.5 * plate});
    }
}

TEST(BodyLawConformance, TheWalkCoversTheList) {
    EXPECT_EQ(std::tuple_size_v<BodyLaws::Laws>, 6u);
    const std::string layout(BodyLaws::layout());
    for (const char* name : {"substrate_contact", "plate_contact", "substrate_lubrication",
                             "stokes_drag", "gravity_buoyancy", "capillary_front"})
        EXPECT_NE(layout.find(name), std::string::npos) << name;
}

TEST(PairLawLimits, EveryDeclaredIntervalRefusesWhatLiesOutside) {
    Config c;
    c.double_layer = true;
    const FilmRecipe rec = make_recipe(c);
    const ForceField ff = make_drying_force_field(c, rec, scale_parameters(c));
    const PairParams& pp = ff.pair_params(rec.cb_species(), rec.cb_species());
    check_every_limit<PairLaws>(pp, std::make_index_sequence<std::tuple_size_v<PairLaws::Laws>>{});
}

// A new body law: its header (here) and one entry in a list. A linear spring that tethers the
// particle to a height, F = -k (z - z_0) ẑ, with a dashpot c on v_z.
struct TetherLaw {
    struct Params {
        double stiffness = 0.0, height = 0.0, damping = 0.0;
    };
    struct State {};
    static constexpr std::string_view name = "tether";
    static constexpr std::array limits{ParamLimit<Params>{"stiffness", &Params::stiffness},
                                       ParamLimit<Params>{"height", &Params::height},
                                       ParamLimit<Params>{"damping", &Params::damping}};
    static void add_force(const BodyGeometry& g, const Params& p, State&, double, BodyForce& f,
                          BodyResistance* r) {
        if (r) r->normal += p.damping;
        f.force.z += -p.stiffness * (g.x.z - p.height) - p.damping * g.v.z;
    }
    static BodyResistance resistance(const BodyGeometry&, const Params& p) {
        BodyResistance r;
        r.normal = p.damping;
        return r;
    }
    static BodyResistance stiffness(const BodyGeometry&, const Params& p) {
        BodyResistance k;
        k.normal = p.stiffness;
        return k;
    }
    static bool keeps(const State&) { return false; }
};

TEST(BodyLawConformance, ANewLawIsItsHeaderAndOneListEntry) {
    using Laws = BodyLawList<StokesDragLaw, TetherLaw>;
    static_assert(BodyLaw<TetherLaw>);
    Laws::Params p{};
    Laws::params<StokesDragLaw>(p) = {0.18, true};
    Laws::params<TetherLaw>(p) = {50.0, 10e-6, 1e-7};
    const Particle q{"CB", 0.75e-6, 2.1e-15, 1187.5};
    walk<Laws>(p, q, {40e-6}, {5e-6, 10e-6, 20e-6});
    // The list sums both, and reports both resistances.
    Laws::State s{};
    BodyResistance r{};
    const BodyForce f =
        Laws::force({{0, 0, 12e-6}, {0, 0, 1e-3}, {}, q.r, q.m, q.density, 0, 0}, p, s, 0.0, &r);
    const double drag = 6 * std::numbers::pi * 0.18 * q.r;
    EXPECT_NEAR(f.force.z, -50.0 * 2e-6 - (1e-7 + drag) * 1e-3, 1e-18);
    EXPECT_NEAR(r.normal, 1e-7 + drag, 1e-20);
    EXPECT_EQ(Laws::layout(), "stokes_drag:1;tether:1;");
}

} // namespace
