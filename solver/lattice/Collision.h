// Collision operators (BGK, MRT, MRT + Smagorinsky LES) with Guo forcing, one node at a time.
#pragma once

#include "solver/core/Real.h"

#include <cmath>
#include <string>

/// Collision operators are inlined into the vectorised node loop whatever their size: a call
/// in the loop body stops vectorisation (measured: MRT + LES ran scalar).
#define LBDEM_KERNEL_INLINE inline __attribute__((always_inline))

namespace lbdem::solver::lattice {

/// The collision models of DESIGN §5.
enum class CollisionModel { Bgk, Mrt, MrtLes };

/// Parse "bgk" / "mrt" / "mrt_les" (the case-file words); throws std::invalid_argument otherwise.
CollisionModel collisionFromName(const std::string& name);
/// The case-file word of a collision model.
const char* collisionName(CollisionModel model);

/// Relaxation parameters of every model, in lattice units.
struct CollisionParams {
    CollisionModel model = CollisionModel::MrtLes;
    Real tau = 0.8;          ///< viscous relaxation time; nu = (tau - 1/2) / 3
    Real s_e = 1.64;         ///< MRT rate of e (Lallemand & Luo 2000 default)
    Real s_eps = 1.54;       ///< MRT rate of eps
    Real s_q = 1.9;          ///< MRT rate of qx, qy
    Real smagorinsky = 0.17; ///< Smagorinsky constant C (LES only)
};

/// BGK: f_i <- f_i - (f_i - f_i^eq) / tau + (1 - 1/(2 tau)) S_i, Guo et al. (2002) source
/// S_i = w_i [3 (c_i - u) + 9 (c_i . u) c_i] . F, with u = (sum c_i f_i + F/2) / rho.
/// Pre: f holds the streamed (pre-collision) populations; post: the post-collision ones.
template <bool kForce>
struct BgkCollision {
    Real omega, fx, fy;

    LBDEM_KERNEL_INLINE void operator()(Real* f) const {
        const Real rho = f[0] + f[1] + f[2] + f[3] + f[4] + f[5] + f[6] + f[7] + f[8];
        Real jx = f[1] - f[3] + f[5] - f[6] - f[7] + f[8];
        Real jy = f[2] - f[4] + f[5] + f[6] - f[7] - f[8];
        if (kForce) { jx += Real(0.5) * fx; jy += Real(0.5) * fy; }
        const Real inv = Real(1) / rho;
        const Real ux = jx * inv, uy = jy * inv;
        const Real usq = Real(1.5) * (ux * ux + uy * uy);
        const Real w0 = Real(4.0 / 9) * rho, w1 = Real(1.0 / 9) * rho, w2 = Real(1.0 / 36) * rho;
        const Real a = ux + uy, b = uy - ux;
        const Real feq[9] = {
            w0 * (1 - usq),
            w1 * (1 + 3 * ux + Real(4.5) * ux * ux - usq),
            w1 * (1 + 3 * uy + Real(4.5) * uy * uy - usq),
            w1 * (1 - 3 * ux + Real(4.5) * ux * ux - usq),
            w1 * (1 - 3 * uy + Real(4.5) * uy * uy - usq),
            w2 * (1 + 3 * a + Real(4.5) * a * a - usq),
            w2 * (1 + 3 * b + Real(4.5) * b * b - usq),
            w2 * (1 - 3 * a + Real(4.5) * a * a - usq),
            w2 * (1 - 3 * b + Real(4.5) * b * b - usq)};
        for (int i = 0; i < 9; ++i) f[i] -= omega * (f[i] - feq[i]);
        if (kForce) addSource(f, ux, uy);
    }

private:
    LBDEM_KERNEL_INLINE void addSource(Real* f, Real ux, Real uy) const {
        constexpr int cx[9] = {0, 1, 0, -1, 0, 1, -1, -1, 1};
        constexpr int cy[9] = {0, 0, 1, 0, -1, 1, 1, -1, -1};
        constexpr Real w[9] = {4.0 / 9, 1.0 / 9, 1.0 / 9, 1.0 / 9, 1.0 / 9,
                               1.0 / 36, 1.0 / 36, 1.0 / 36, 1.0 / 36};
        const Real k = 1 - Real(0.5) * omega;
        for (int i = 0; i < 9; ++i) {
            const Real cu = cx[i] * ux + cy[i] * uy;
            f[i] += k * w[i] * ((3 * (cx[i] - ux) + 9 * cu * cx[i]) * fx +
                                (3 * (cy[i] - uy) + 9 * cu * cy[i]) * fy);
        }
    }
};

/// MRT after Lallemand & Luo (2000), moments (rho, e, eps, jx, qx, jy, qy, pxx, pxy) with the
/// M of DESIGN §5: m* = m - S (m - m^eq) + (I - S/2) M S^Guo, f = M^-1 m*, where
/// M^-1 = M^T diag(1/9, 1/36, 1/36, 1/6, 1/12, 1/6, 1/12, 1/4, 1/4).
/// With kLes the shear rate is s_nu = 1/tau*, tau* = (tau + sqrt(tau^2 + 18 C^2 sqrt(2Q)/rho))/2,
/// Q = Pi_neq : Pi_neq (Hou et al. 1996; the force correction of Pi_neq is neglected).
template <bool kLes, bool kForce>
struct MrtCollision {
    Real sNu, sE, sEps, sQ, tau, c2x18, fx, fy;

    LBDEM_KERNEL_INLINE void operator()(Real* f) const {
        const Real rho = f[0] + f[1] + f[2] + f[3] + f[4] + f[5] + f[6] + f[7] + f[8];
        const Real sumAxis = f[1] + f[2] + f[3] + f[4];
        const Real sumDiag = f[5] + f[6] + f[7] + f[8];
        const Real e = -4 * f[0] - sumAxis + 2 * sumDiag;
        const Real eps = 4 * f[0] - 2 * sumAxis + sumDiag;
        Real jx = f[1] - f[3] + f[5] - f[6] - f[7] + f[8];
        Real jy = f[2] - f[4] + f[5] + f[6] - f[7] - f[8];
        const Real qx = -2 * (f[1] - f[3]) + f[5] - f[6] - f[7] + f[8];
        const Real qy = -2 * (f[2] - f[4]) + f[5] + f[6] - f[7] - f[8];
        const Real pxx = f[1] - f[2] + f[3] - f[4];
        const Real pxy = f[5] - f[6] + f[7] - f[8];
        Real gx = 0, gy = 0; // physical momentum shift F/2 (Guo)
        if (kForce) { gx = Real(0.5) * fx; gy = Real(0.5) * fy; }
        const Real inv = Real(1) / rho;
        const Real px = jx + gx, py = jy + gy; // rho u
        const Real j2 = (px * px + py * py) * inv;
        const Real de = e - (-2 * rho + 3 * j2);
        const Real dEps = eps - (rho - 3 * j2);
        const Real dQx = qx + px, dQy = qy + py;
        const Real dPxx = pxx - (px * px - py * py) * inv;
        const Real dPxy = pxy - px * py * inv;
        Real sNuHere = sNu;
        if (kLes) {
            // Pi_neq from the non-equilibrium moments: Pi_xx = (de/3 + dPxx)/2, Pi_yy = (de/3 - dPxx)/2.
            const Real pxxN = Real(0.5) * (de * Real(1.0 / 3) + dPxx);
            const Real pyyN = Real(0.5) * (de * Real(1.0 / 3) - dPxx);
            const Real q = pxxN * pxxN + pyyN * pyyN + 2 * dPxy * dPxy;
            const Real tauStar =
                Real(0.5) * (tau + std::sqrt(tau * tau + c2x18 * std::sqrt(2 * q) * inv));
            sNuHere = Real(1) / tauStar;
        }
        Real me = -sE * de, mEps = -sEps * dEps, mQx = -sQ * dQx, mQy = -sQ * dQy;
        Real mPxx = -sNuHere * dPxx, mPxy = -sNuHere * dPxy, mJx = 0, mJy = 0;
        if (kForce) {
            const Real ux = px * inv, uy = py * inv, uf = ux * fx + uy * fy;
            me += (1 - Real(0.5) * sE) * 6 * uf;
            mEps -= (1 - Real(0.5) * sEps) * 6 * uf;
            mJx = fx;
            mJy = fy;
            mQx -= (1 - Real(0.5) * sQ) * fx;
            mQy -= (1 - Real(0.5) * sQ) * fy;
            mPxx += (1 - Real(0.5) * sNuHere) * 2 * (ux * fx - uy * fy);
            mPxy += (1 - Real(0.5) * sNuHere) * (ux * fy + uy * fx);
        }
        // f += M^T D dm, row by row of M (DESIGN §5).
        const Real a = me * Real(1.0 / 36), b = mEps * Real(1.0 / 36);
        const Real cx = mJx * Real(1.0 / 6), dx = mQx * Real(1.0 / 12);
        const Real cy = mJy * Real(1.0 / 6), dy = mQy * Real(1.0 / 12);
        const Real p = mPxx * Real(0.25), s = mPxy * Real(0.25);
        const Real axis = -a - 2 * b, diag = 2 * a + b;
        f[0] += -4 * a + 4 * b;
        f[1] += axis + cx - 2 * dx + p;
        f[2] += axis + cy - 2 * dy - p;
        f[3] += axis - cx + 2 * dx + p;
        f[4] += axis - cy + 2 * dy - p;
        f[5] += diag + cx + dx + cy + dy + s;
        f[6] += diag - cx - dx + cy + dy - s;
        f[7] += diag - cx - dx - cy - dy + s;
        f[8] += diag + cx + dx - cy - dy - s;
    }
};

} // namespace lbdem::solver::lattice
