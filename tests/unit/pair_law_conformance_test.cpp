// SPDX-License-Identifier: MIT
// Conformance of every law in PairLaws to the contract of forces/pair_law.hpp, through each law's
// own add_force (not its free functions), so that a law added later is checked by adding it to the
// list: for the drying film's CB-CB and largest-NCM-CB pairs (every law switched on, the double
// layer included), in overlap and at two gaps,
//   - Newton's third law with angular momentum: j receives -F_i, and τ_i + τ_j = D n × F_i;
//   - rigid-body invariance: moving the pair as one rigid body changes no force;
//   - the dissipative part of add_force is resistance() applied to the velocities, and the
//     resistance add_force reports is resistance();
//   - stiffness() is -dF/dx of the conservative part: normal by central differences in the gap
//     (in overlap at least that: a bound, as the guard needs it), sliding by a tangential step of
//     the history.
#include "drydem/drying/law_parameters.hpp"
#include "drydem/drying/scaling.hpp"
#include "drydem/forces/force_field.hpp"
#include <gtest/gtest.h>
#include <cmath>
#include <string>
#include <tuple>
#include <utility>

namespace {
using namespace drydem;

template <class List>
struct LawsOf;
template <PairLaw... Ls>
struct LawsOf<PairLawList<Ls...>> {
    using type = std::tuple<Ls...>;
};
using AllLaws = LawsOf<PairLaws>::type;

struct Pair {
    std::string name;
    double r_i, r_j, m_i, m_j;
    PairParams params;
};

/// The drying film's force field with every pair law on (the double layer too), paper scheme.
std::vector<Pair> film_pairs() {
    Config c;
    c.double_layer = true;
    const FilmRecipe r = make_recipe(c);
    const ForceField ff = make_drying_force_field(c, r, scale_parameters(c));
    const int cb = r.cb_species(), ncm = cb - 1; // the largest NCM class is the last
    auto mass = [&](int s) {
        return sphere_volume(0.5 * r.species[std::size_t(s)].diameter) *
               r.species[std::size_t(s)].density;
    };
    auto rad = [&](int s) { return 0.5 * r.species[std::size_t(s)].diameter; };
    return {{"CB-CB", rad(cb), rad(cb), mass(cb), mass(cb), ff.pair_params(cb, cb)},
            {"NCM-CB", rad(ncm), rad(cb), mass(ncm), mass(cb), ff.pair_params(ncm, cb)}};
}

const Vec3 kNormal = Vec3{0.3, -0.5, 0.81} / norm(Vec3{0.3, -0.5, 0.81});

struct Motion {
    Vec3 v_i, v_j, w_i, w_j;
};

PairGeometry at(const Pair& p, double gap, const Motion& u) {
    const double d = p.r_i + p.r_j + gap;
    return make_pair_geometry(d * kNormal, d, p.r_i, p.r_j, p.m_i, p.m_j, u.v_i, u.v_j, u.w_i,
                              u.w_j);
}

template <class L>
PairForce force_of(const Pair& p, double gap, const Motion& u, double dt = 0.0,
                   PairResistance* r = nullptr) {
    typename L::State s{};
    PairForce f{};
    L::add_force(at(p, gap, u), PairLaws::params<L>(p.params), s, dt, f, r);
    return f;
}

double scale_of(const PairForce& a, const PairForce& b) {
    return std::max({norm(a.force_i), norm(b.force_i), 1e-30});
}

void expect_close(const Vec3& a, const Vec3& b, double tol, const std::string& what) {
    EXPECT_LE(norm(a - b), tol) << what << ": (" << a.x << ", " << a.y << ", " << a.z << ") vs ("
                                << b.x << ", " << b.y << ", " << b.z << ")";
}

template <class L>
void check_law(const Pair& p, double gap) {
    const std::string where =
        std::string(L::name) + ", " + p.name + ", gap " + std::to_string(gap * 1e9) + " nm";
    // Small velocities: the contact sticks (no Coulomb limit) and every law stays linear in them.
    const Motion u{
        {1e-4, -2e-4, 3e-4}, {-2e-4, 1e-4, -1e-4}, {30.0, -50.0, 20.0}, {-10.0, 40.0, 60.0}};
    const PairForce rest = force_of<L>(p, gap, {}), moving = force_of<L>(p, gap, u);
    const double d = p.r_i + p.r_j + gap, tol = 1e-9 * scale_of(rest, moving);

    // Newton's third law with angular momentum (j receives -F_i by the contract's form).
    expect_close(moving.torque_i + moving.torque_j, cross(d * kNormal, moving.force_i), tol * d,
                 where + " torques");

    // Rigid-body motion of the pair: translation V and rotation Ω about i.
    const Vec3 V{2e-4, -1e-4, 5e-5}, W{40.0, -20.0, 30.0};
    const PairForce rigid = force_of<L>(p, gap, {V, V + cross(W, d * kNormal), W, W});
    expect_close(rigid.force_i, rest.force_i, tol, where + " rigid force");
    expect_close(rigid.torque_i, rest.torque_i, tol * d, where + " rigid torque i");
    expect_close(rigid.torque_j, rest.torque_j, tol * d, where + " rigid torque j");

    // The dissipative part is resistance() on the velocities, and add_force reports it.
    PairResistance r = L::resistance(at(p, gap, u), PairLaws::params<L>(p.params)), reported{};
    r.lever_i = p.r_i + 0.5 * gap;
    r.lever_j = p.r_j + 0.5 * gap;
    (void)force_of<L>(p, gap, u, 0.0, &reported);
    EXPECT_NEAR(reported.normal, r.normal, 1e-12 * std::abs(r.normal)) << where;
    EXPECT_NEAR(reported.sliding, r.sliding, 1e-12 * std::abs(r.sliding)) << where;
    const PairForce dissipative = resistance_force(r, kNormal, u.v_i - u.v_j, u.w_i, u.w_j);
    expect_close(moving.force_i - rest.force_i, dissipative.force_i, tol,
                 where + " dissipative force");
    expect_close(moving.torque_i - rest.torque_i, dissipative.torque_i, tol * d,
                 where + " dissipative torque i");
    expect_close(moving.torque_j - rest.torque_j, dissipative.torque_j, tol * d,
                 where + " dissipative torque j");

    // Stiffness: -dF_n/dh by central differences at rest (its magnitude: the van der Waals snap-in
    // has a negative stiffness, pair_law.hpp), and the sliding spring by one history step.
    const PairResistance k =
        L::stiffness(at(p, gap, {}), at(p, gap, {}), PairLaws::params<L>(p.params));
    const double h = 1e-6 * p.r_j;
    const double dfdh = (dot(force_of<L>(p, gap + h, {}).force_i, kNormal) -
                         dot(force_of<L>(p, gap - h, {}).force_i, kNormal)) /
                        (2 * h);
    const double noise = 1e-9 * norm(rest.force_i) / h + 1e-12; // rounding of F over the step
    if (gap > 0.0)
        EXPECT_NEAR(k.normal, std::abs(dfdh), 1e-5 * std::abs(dfdh) + noise)
            << where << " normal stiffness";
    else // a bound in overlap: the double layer keeps its contact stiffness where its force is constant
        EXPECT_GE(k.normal, std::abs(dfdh) - noise) << where << " normal stiffness bound";
    const Vec3 t = perp(Vec3{1.0, 0.0, 0.0}, kNormal) / norm(perp(Vec3{1.0, 0.0, 0.0}, kNormal));
    const double dt = 1e-12, v = 1e-4;
    const PairForce stepped = force_of<L>(p, gap, {v * t, {}, {}, {}}, dt),
                    unstepped = force_of<L>(p, gap, {v * t, {}, {}, {}});
    const double spring = -dot(stepped.force_i - unstepped.force_i, t) / (v * dt);
    EXPECT_NEAR(k.sliding, spring, 1e-6 * std::abs(k.sliding) + 1e-9)
        << where << " sliding stiffness";
}

/// The quasi-static step's linearisation of law L given the kept state s (pair_law.hpp: the
/// optional tangent and resistance(g, p, s), else stiffness and resistance).
template <class L>
std::pair<PairResistance, PairResistance>
linearised(const PairGeometry& g, const typename L::Params& lp, const typename L::State& s) {
    PairResistance r, k;
    if constexpr (requires { L::resistance(g, lp, s); })
        r = L::resistance(g, lp, s);
    else
        r = L::resistance(g, lp);
    if constexpr (requires { L::tangent(g, lp, s); })
        k = L::tangent(g, lp, s);
    else
        k = L::stiffness(g, g, lp);
    return {r, k};
}

/// With nothing kept the linearisation is resistance() and stiffness(); after a long slide (the
/// spring cut to Coulomb's limit) the sliding stiffness and damping are what one more history
/// step and the force at a sliding velocity give: none for a contact that slides.
template <class L>
void check_linearisation(const Pair& p, double gap) {
    const std::string where =
        std::string(L::name) + ", " + p.name + ", gap " + std::to_string(gap * 1e9) + " nm";
    const auto& lp = PairLaws::params<L>(p.params);
    const PairGeometry g = at(p, gap, {});
    const auto [r0, k0] = linearised<L>(g, lp, typename L::State{});
    const PairResistance r = L::resistance(g, lp), k = L::stiffness(g, g, lp);
    EXPECT_EQ(r0.normal, r.normal) << where;
    EXPECT_EQ(r0.sliding, r.sliding) << where;
    EXPECT_EQ(k0.normal, k.normal) << where;
    EXPECT_EQ(k0.sliding, k.sliding) << where;
    // Slide: 1 um along t in one step, far beyond any spring's Coulomb limit.
    const Vec3 t = perp(Vec3{1.0, 0.0, 0.0}, kNormal) / norm(perp(Vec3{1.0, 0.0, 0.0}, kNormal));
    typename L::State s{};
    PairForce f{};
    L::add_force(at(p, gap, {1.0 * t, {}, {}, {}}), lp, s, 1e-6, f, nullptr);
    const auto [r1, k1] = linearised<L>(g, lp, s);
    // Two more steps in the same direction: the force's change per displacement, and the damping
    // the law reports while it keeps sliding.
    const double dt = 1e-12, v = 1e-4;
    PairResistance reported{};
    PairForce f1{}, f2{};
    L::add_force(at(p, gap, {v * t, {}, {}, {}}), lp, s, dt, f1, &reported);
    L::add_force(at(p, gap, {v * t, {}, {}, {}}), lp, s, dt, f2, nullptr);
    const double spring = -dot(f2.force_i - f1.force_i, t) / (v * dt);
    EXPECT_NEAR(k1.sliding, spring, 1e-6 * std::abs(k.sliding) + 1e-9) << where << " sliding";
    EXPECT_EQ(k1.normal, k.normal) << where;
    EXPECT_EQ(r1.sliding, reported.sliding) << where << " sliding damping";
}

template <std::size_t... K>
void check_every_law(const Pair& p, double gap, std::index_sequence<K...>) {
    (check_law<std::tuple_element_t<K, AllLaws>>(p, gap), ...);
    (check_linearisation<std::tuple_element_t<K, AllLaws>>(p, gap), ...);
}

TEST(PairLawConformance, EveryLawOfTheListKeepsTheContract) {
    for (const Pair& p : film_pairs())
        for (double gap : {-0.01 * p.r_j, 0.02e-6, 0.3e-6})
            check_every_law(p, gap, std::make_index_sequence<std::tuple_size_v<AllLaws>>{});
}

// The pair loop takes the kick's self-stiffness from the same evaluation as the force
// (PairLaws::force with `tangent`): to the bit, it is PairLaws::tangent of the state that step
// leaves, with the force unchanged, for sticking and sliding, elastic and elastic-plastic
// contacts, and at gaps.
TEST(PairLawConformance, TheFusedTangentIsTheTangentOfTheStateLeft) {
    const Vec3 t = perp(Vec3{1.0, 0.0, 0.0}, kNormal) / norm(perp(Vec3{1.0, 0.0, 0.0}, kNormal));
    int sticking = 0, sliding = 0;
    for (Pair p : film_pairs())
        for (double yield : {0.0, 2e8}) {
            PairLaws::params<HertzMindlinLaw>(p.params).yield_pressure = yield;
            for (double gap : {-0.01 * p.r_j, -0.002 * p.r_j, 0.02e-6, 0.3e-6})
                for (double speed : {1e-6, 1.0}) { // 1 pm a step sticks, 1 um slides
                    const std::string where = p.name + ", p_y " + std::to_string(yield) + ", gap " +
                                              std::to_string(gap * 1e9) + " nm, speed " +
                                              std::to_string(speed);
                    const PairGeometry g = at(p, gap, {speed * t, {}, {}, {}});
                    PairState fused{}, apart{};
                    PairResistance r_fused, r_apart, k_fused;
                    const PairForce f_fused =
                        PairLaws::force(g, p.params, fused, 1e-6, &r_fused, &k_fused);
                    const PairForce f_apart = PairLaws::force(g, p.params, apart, 1e-6, &r_apart);
                    const PairResistance k_apart = PairLaws::tangent(g, p.params, apart);
                    EXPECT_EQ(k_fused.normal, k_apart.normal) << where;
                    EXPECT_EQ(k_fused.sliding, k_apart.sliding) << where;
                    EXPECT_EQ(k_fused.rolling, k_apart.rolling) << where;
                    EXPECT_EQ(k_fused.twisting, k_apart.twisting) << where;
                    EXPECT_EQ(r_fused.normal, r_apart.normal) << where;
                    EXPECT_EQ(r_fused.sliding, r_apart.sliding) << where;
                    EXPECT_EQ(f_fused.force_i.x, f_apart.force_i.x) << where;
                    EXPECT_EQ(f_fused.force_i.y, f_apart.force_i.y) << where;
                    EXPECT_EQ(f_fused.force_i.z, f_apart.force_i.z) << where;
                    EXPECT_EQ(f_fused.torque_j.z, f_apart.torque_j.z) << where;
                    if (gap < 0.0) {
                        EXPECT_GT(k_fused.normal, 0.0) << where;
                        (k_fused.sliding > 0.0 ? sticking : sliding) += 1;
                    }
                }
        }
    EXPECT_EQ(sticking, 8); // both branches of the Coulomb test were reached
    EXPECT_EQ(sliding, 8);
}

// The walk above reaches every law the list holds.
TEST(PairLawConformance, TheWalkCoversTheList) {
    EXPECT_EQ(std::tuple_size_v<AllLaws>, 4u);
    const std::string layout(PairLaws::layout());
    for (const char* name : {"hertz_mindlin", "van_der_waals", "lubrication", "double_layer"})
        EXPECT_NE(layout.find(name), std::string::npos) << name;
}

} // namespace
