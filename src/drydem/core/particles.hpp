// SPDX-License-Identifier: MIT
// Particle store: structure of arrays, SI units, double precision. Identity (id) is separate from
// storage position, so particles can be re-sorted for memory locality while contact history,
// output and restarts stay keyed by id (ARCHITECTURE.md).
#pragma once
#include "drydem/core/sphere.hpp"
#include "drydem/core/vec3.hpp"
#include <cstdint>
#include <numbers>
#include <vector>

namespace drydem {

struct ParticleStore {
    std::vector<std::uint32_t> id;     ///< global, stable particle id
    std::vector<std::uint8_t> species; ///< index into the species table
    std::vector<double> radius;        ///< [m]
    std::vector<double> density;       ///< particle density [kg/m^3] (CB: carbon + pore NMP, M-1.3)
    std::vector<double> mass;          ///< [kg]
    std::vector<double> inv_mass;      ///< [1/kg]
    std::vector<double> inv_inertia;   ///< 1/I with I = (2/5) m r^2 [1/(kg m^2)]
    std::vector<Vec3> position;        ///< [m], x and y wrapped into the box
    std::vector<Vec3> velocity;        ///< [m/s]
    std::vector<Vec3> omega;           ///< angular velocity [rad/s]
    std::vector<Vec3> force;           ///< [N]
    std::vector<Vec3> torque;          ///< [N m]

    [[nodiscard]] std::size_t size() const { return id.size(); }

    /// Appends a sphere at rest; mass and inertia follow from radius and density.
    void add(std::uint32_t pid, std::uint8_t sp, double r, double rho, const Vec3& x) {
        const double m = rho * sphere_volume(r);
        id.push_back(pid);
        species.push_back(sp);
        radius.push_back(r);
        density.push_back(rho);
        mass.push_back(m);
        inv_mass.push_back(1.0 / m);
        inv_inertia.push_back(1.0 / (0.4 * m * r * r));
        position.push_back(x);
        velocity.push_back({});
        omega.push_back({});
        force.push_back({});
        torque.push_back({});
    }

    /// Density scaling: the spheres of `sp` get `factor` times their mass and moment of inertia,
    /// their density (what gravity and buoyancy read) stays physical. For quasi-static loading
    /// only: inertia is what it distorts (docs/calendering.md).
    void scale_inertia(std::uint8_t sp, double factor) {
        for (std::size_t i = 0; i < size(); ++i)
            if (species[i] == sp) {
                mass[i] *= factor;
                inv_mass[i] /= factor;
                inv_inertia[i] /= factor;
            }
    }

    /// Sphere i takes the radius r with its mass kept (a compacting agglomerate): its density
    /// rises as 1/r³, its moment of inertia (2/5) m r² falls.
    void resize_sphere(std::size_t i, double r) {
        const double ratio = radius[i] / r;
        density[i] *= ratio * ratio * ratio;
        radius[i] = r;
        inv_inertia[i] = 1.0 / (0.4 * mass[i] * r * r);
    }

    /// Sphere i takes the density ρ with its radius kept (an agglomerate taking solid into its
    /// pores): mass and moment of inertia follow, with any density scaling of its mass kept.
    void set_density(std::size_t i, double rho) {
        const double ratio = rho / density[i];
        density[i] = rho;
        mass[i] *= ratio;
        inv_mass[i] /= ratio;
        inv_inertia[i] /= ratio;
    }

    /// Reorders every per-particle array so that new index k holds old index order[k]; an order
    /// shorter than the store keeps only the particles it lists.
    void permute(const std::vector<std::uint32_t>& order);
};

} // namespace drydem
