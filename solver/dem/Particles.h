// Discs as a structure of arrays: state, derived mass properties, forces and external loads.
#pragma once

#include "solver/core/Real.h"

#include <cstddef>
#include <vector>

namespace lbdem::solver::dem {

/// All discs of a system, one array per quantity (SI units, per unit thickness).
/// x points right / downslope, y up / normal to the slope; omega is counter-clockwise positive.
struct Particles {
    std::vector<Real> x, y;           ///< centre [m]
    std::vector<Real> vx, vy;         ///< velocity [m/s]
    std::vector<Real> omega;          ///< angular velocity [rad/s]
    std::vector<Real> fx, fy;         ///< total force of the last evaluation [N/m]
    std::vector<Real> torque;         ///< total torque of the last evaluation [N]
    std::vector<Real> radius;         ///< contact radius R [m]
    std::vector<Real> mass;           ///< rho pi R^2 [kg/m]
    std::vector<Real> inertia;        ///< m R^2 / 2 [kg m]
    std::vector<Real> ext_fx, ext_fy; ///< external force held fixed across steps (coupling) [N/m]
    std::vector<Real> ext_torque;     ///< external torque held fixed across steps [N]

    /// Number of discs.
    std::size_t size() const { return x.size(); }

    /// Reserve room for n discs so that adding them does not reallocate.
    void reserve(std::size_t n) {
        for (auto* a : arrays())
            a->reserve(n);
    }

    /// Append a disc at rest; mass and inertia follow from the radius and density.
    std::size_t add(Real px, Real py, Real r, Real m) {
        for (auto* a : arrays())
            a->push_back(0);
        const std::size_t i = x.size() - 1;
        x[i] = px;
        y[i] = py;
        radius[i] = r;
        mass[i] = m;
        inertia[i] = m * r * r / 2;
        return i;
    }

    /// Pointers to every per-disc array (for resizing and permuting them together).
    std::vector<std::vector<Real>*> arrays() {
        return {&x,      &y,      &vx,   &vy,      &omega,  &fx,     &fy,
                &torque, &radius, &mass, &inertia, &ext_fx, &ext_fy, &ext_torque};
    }
};

} // namespace lbdem::solver::dem
