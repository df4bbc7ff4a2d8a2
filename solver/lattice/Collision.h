// Collision operators (BGK, MRT, MRT + Smagorinsky LES) with Guo forcing, one node at a time.
#pragma once

#include "solver/core/EnumWords.h"
#include "solver/core/Real.h"

#include <array>
#include <cmath>

/// Collision operators are inlined into the vectorised node loop whatever their size: a call
/// in the loop body stops vectorisation (measured: MRT + LES ran scalar).
#define LBDEM_KERNEL_INLINE inline __attribute__((always_inline))

namespace lbdem::solver::lattice {

/// The collision models of docs/design.md §5.
enum class CollisionModel { Bgk, Mrt, MrtLes };

/// The case-file word of each collision model (fluid.collision).
constexpr std::array<EnumWord<CollisionModel>, 3> enumWords(CollisionModel) {
    return {{{CollisionModel::Bgk, "bgk"},
             {CollisionModel::Mrt, "mrt"},
             {CollisionModel::MrtLes, "mrt_les"}}};
}

/// Relaxation parameters of every model, in lattice units.
struct CollisionParams {
    CollisionModel model = CollisionModel::MrtLes;
    Real tau = 0.8;          ///< viscous relaxation time; nu = (tau - 1/2) / 3
    Real s_e = 1.64;         ///< MRT rate of e (Lallemand & Luo 2000 default)
    Real s_eps = 1.54;       ///< MRT rate of eps
    Real s_q = 1.9;          ///< MRT rate of qx, qy
    Real smagorinsky = 0.17; ///< Smagorinsky constant C (LES only)
};

/// Lambda = (tau - 1/2)(1/s_q - 1/2) at which straight bounce-back walls sit exactly half-way
/// between nodes, whatever tau (Ginzburg & d'Humieres 2003).
constexpr double kHalfWayLambda = 3.0 / 16.0;

/// The MRT rate s_q that gives the "magic" parameter Lambda = (tau - 1/2)(1/s_q - 1/2) at tau.
inline double sqForMagicLambda(double tau, double lambda) {
    return 1.0 / (0.5 + lambda / (tau - 0.5));
}

template <bool kLes, bool kForce> struct MrtCollision;

/// BGK: f_i <- f_i - (f_i - f_i^eq) / tau + (1 - 1/(2 tau)) S_i, Guo et al. (2002) source
/// S_i = w_i [3 (c_i - u) + 9 (c_i . u) c_i] . F, with u = (sum c_i f_i + F/2) / rho.
/// Pre: f holds the streamed (pre-collision) populations; post: the post-collision ones.
/// apply<T, kShifted>() runs in arithmetic T; with kShifted, f holds the deviations f_i - w_i
/// (float storage's shift) and stays so. The shifted form runs as the MRT operator with every
/// rate 1/tau, which is this BGK operator with its Guo source exactly: in moment space mass and
/// momentum are left untouched, whereas f_i - (f_i - f_i^eq)/tau rounds each f_i^eq and, in
/// float, lost momentum at 1e-10 per step in step with the flow (the Taylor-Green vortex drifted
/// 7.9e-5 from double in 2000 steps at tau = 0.51; 2.8e-7 through the moments).
template <bool kForce> struct BgkCollision {
    Real omega, fx, fy;

    /// Collide the full populations f_i in double.
    LBDEM_KERNEL_INLINE void operator()(Real* f) const { apply<Real, false>(f); }

    template <class T, bool kShifted> LBDEM_KERNEL_INLINE void apply(T* f) const {
        if constexpr (kShifted) {
            MrtCollision<false, kForce>{omega, omega, omega, omega, 1 / omega, 0, fx, fy}
                .template apply<T, true>(f);
        } else {
            full(f);
        }
    }

private:
    template <class T> LBDEM_KERNEL_INLINE void full(T* f) const {
        const T rho = f[0] + f[1] + f[2] + f[3] + f[4] + f[5] + f[6] + f[7] + f[8];
        T jx = f[1] - f[3] + f[5] - f[6] - f[7] + f[8];
        T jy = f[2] - f[4] + f[5] + f[6] - f[7] - f[8];
        if (kForce) {
            jx += T(0.5) * T(fx);
            jy += T(0.5) * T(fy);
        }
        const T inv = T(1) / rho;
        const T ux = jx * inv, uy = jy * inv;
        const T usq = T(1.5) * (ux * ux + uy * uy);
        const T w0 = T(4.0 / 9) * rho, w1 = T(1.0 / 9) * rho, w2 = T(1.0 / 36) * rho;
        const T a = ux + uy, b = uy - ux;
        const T feq[9] = {w0 * (1 - usq),
                          w1 * (1 + 3 * ux + T(4.5) * ux * ux - usq),
                          w1 * (1 + 3 * uy + T(4.5) * uy * uy - usq),
                          w1 * (1 - 3 * ux + T(4.5) * ux * ux - usq),
                          w1 * (1 - 3 * uy + T(4.5) * uy * uy - usq),
                          w2 * (1 + 3 * a + T(4.5) * a * a - usq),
                          w2 * (1 + 3 * b + T(4.5) * b * b - usq),
                          w2 * (1 - 3 * a + T(4.5) * a * a - usq),
                          w2 * (1 - 3 * b + T(4.5) * b * b - usq)};
        const T om = T(omega);
        for (int i = 0; i < 9; ++i)
            f[i] -= om * (f[i] - feq[i]);
        if (kForce) addSource(f, ux, uy);
    }

    template <class T> LBDEM_KERNEL_INLINE void addSource(T* f, T ux, T uy) const {
        constexpr int cx[9] = {0, 1, 0, -1, 0, 1, -1, -1, 1};
        constexpr int cy[9] = {0, 0, 1, 0, -1, 1, 1, -1, -1};
        constexpr T w[9] = {T(4.0 / 9),  T(1.0 / 9),  T(1.0 / 9),  T(1.0 / 9), T(1.0 / 9),
                            T(1.0 / 36), T(1.0 / 36), T(1.0 / 36), T(1.0 / 36)};
        const T k = 1 - T(0.5) * T(omega), gx = T(fx), gy = T(fy);
        for (int i = 0; i < 9; ++i) {
            const T cu = cx[i] * ux + cy[i] * uy;
            f[i] += k * w[i] *
                    ((3 * (cx[i] - ux) + 9 * cu * cx[i]) * gx +
                     (3 * (cy[i] - uy) + 9 * cu * cy[i]) * gy);
        }
    }
};

/// MRT after Lallemand & Luo (2000), moments (rho, e, eps, jx, qx, jy, qy, pxx, pxy) with the
/// M of docs/design.md §5: m* = m - S (m - m^eq) + (I - S/2) M S^Guo, f = M^-1 m*, where
/// M^-1 = M^T diag(1/9, 1/36, 1/36, 1/6, 1/12, 1/6, 1/12, 1/4, 1/4).
/// With kLes the shear rate is s_nu = 1/tau*, tau* = (tau + sqrt(tau^2 + 18 C^2 sqrt(2Q)/rho))/2,
/// Q = Pi_neq : Pi_neq (Hou et al. 1996; the force correction of Pi_neq is neglected).
template <bool kLes, bool kForce> struct MrtCollision {
    Real sNu, sE, sEps, sQ, tau, c2x18, fx, fy;

    /// Collide the full populations f_i in double.
    LBDEM_KERNEL_INLINE void operator()(Real* f) const { apply<Real, false>(f); }

    /// Collide in arithmetic T; kShifted: f holds f_i - w_i (see BgkCollision).
    template <class T, bool kShifted> LBDEM_KERNEL_INLINE void apply(T* f) const {
        if constexpr (kShifted)
            shifted(f);
        else
            full(f);
    }

private:
    /// The full populations, in the order of operations double storage has always used.
    template <class T> LBDEM_KERNEL_INLINE void full(T* f) const {
        const T sNuT = T(sNu), sET = T(sE), sEpsT = T(sEps), sQT = T(sQ), tauT = T(tau),
                c2x18T = T(c2x18);
        const T fxT = T(fx), fyT = T(fy);
        const T sum = f[0] + f[1] + f[2] + f[3] + f[4] + f[5] + f[6] + f[7] + f[8]; // rho
        const T sumAxis = f[1] + f[2] + f[3] + f[4];
        const T sumDiag = f[5] + f[6] + f[7] + f[8];
        const T e = -4 * f[0] - sumAxis + 2 * sumDiag;
        const T eps = 4 * f[0] - 2 * sumAxis + sumDiag;
        T jx = f[1] - f[3] + f[5] - f[6] - f[7] + f[8];
        T jy = f[2] - f[4] + f[5] + f[6] - f[7] - f[8];
        const T qx = -2 * (f[1] - f[3]) + f[5] - f[6] - f[7] + f[8];
        const T qy = -2 * (f[2] - f[4]) + f[5] + f[6] - f[7] - f[8];
        const T pxx = f[1] - f[2] + f[3] - f[4];
        const T pxy = f[5] - f[6] + f[7] - f[8];
        T gx = 0, gy = 0; // physical momentum shift F/2 (Guo)
        if (kForce) {
            gx = T(0.5) * fxT;
            gy = T(0.5) * fyT;
        }
        const T inv = T(1) / sum;
        const T px = jx + gx, py = jy + gy; // rho u
        const T j2 = (px * px + py * py) * inv;
        const T de = e - (-2 * sum + 3 * j2);
        const T dEps = eps - (sum - 3 * j2);
        const T dQx = qx + px, dQy = qy + py;
        const T dPxx = pxx - (px * px - py * py) * inv;
        const T dPxy = pxy - px * py * inv;
        T sNuHere = sNuT;
        if (kLes) {
            // Pi_neq from the non-equilibrium moments: Pi_xx = (de/3 + dPxx)/2, Pi_yy = (de/3 -
            // dPxx)/2.
            const T pxxN = T(0.5) * (de * T(1.0 / 3) + dPxx);
            const T pyyN = T(0.5) * (de * T(1.0 / 3) - dPxx);
            const T q = pxxN * pxxN + pyyN * pyyN + 2 * dPxy * dPxy;
            const T tauStar =
                T(0.5) * (tauT + std::sqrt(tauT * tauT + c2x18T * std::sqrt(2 * q) * inv));
            sNuHere = T(1) / tauStar;
        }
        T me = -sET * de, mEps = -sEpsT * dEps, mQx = -sQT * dQx, mQy = -sQT * dQy;
        T mPxx = -sNuHere * dPxx, mPxy = -sNuHere * dPxy, mJx = 0, mJy = 0;
        if (kForce) {
            const T ux = px * inv, uy = py * inv, uf = ux * fxT + uy * fyT;
            me += (1 - T(0.5) * sET) * 6 * uf;
            mEps -= (1 - T(0.5) * sEpsT) * 6 * uf;
            mJx = fxT;
            mJy = fyT;
            mQx -= (1 - T(0.5) * sQT) * fxT;
            mQy -= (1 - T(0.5) * sQT) * fyT;
            mPxx += (1 - T(0.5) * sNuHere) * 2 * (ux * fxT - uy * fyT);
            mPxy += (1 - T(0.5) * sNuHere) * (ux * fyT + uy * fxT);
        }
        // f += M^T D dm, row by row of M (docs/design.md §5).
        const T a = me * T(1.0 / 36), b = mEps * T(1.0 / 36);
        const T cx = mJx * T(1.0 / 6), dx = mQx * T(1.0 / 12);
        const T cy = mJy * T(1.0 / 6), dy = mQy * T(1.0 / 12);
        const T p = mPxx * T(0.25), s = mPxy * T(0.25);
        const T axis = -a - 2 * b, diag = 2 * a + b;
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

    /// The deviations f_i - w_i (float storage), the operator of full() in fewer operations: the
    /// moments from the sums and differences of opposite pairs, each rate folded with its row of
    /// M^-1 into one factor, no arithmetic on an absent force. The rest state's moments are
    /// rho = 1, e = -2, eps = 1 and zero otherwise, so in the shifted sums (primes), with
    /// rho' = rho - 1: e - e^eq = e' + 2 rho' - 3 j^2/rho, eps - eps^eq = eps' - rho' + 3 j^2/rho.
    template <class T> LBDEM_KERNEL_INLINE void shifted(T* f) const {
        const T a13 = f[1] + f[3], d13 = f[1] - f[3], a24 = f[2] + f[4], d24 = f[2] - f[4];
        const T a57 = f[5] + f[7], d57 = f[5] - f[7], a68 = f[6] + f[8], d68 = f[6] - f[8];
        const T axis = a13 + a24, diag = a57 + a68, xDiag = d57 - d68, yDiag = d57 + d68;
        const T sum = f[0] + axis + diag;     // rho - 1
        T px = d13 + xDiag, py = d24 + yDiag; // rho u: j, plus F/2 under a force (Guo)
        if constexpr (kForce) {
            px += T(0.5 * fx);
            py += T(0.5 * fy);
        }
        const T inv = 1 / (1 + sum), ux = px * inv, uy = py * inv;
        const T xx = px * ux, yy = py * uy, j2 = xx + yy;
        const T de = (2 * diag - axis - 4 * f[0]) + 2 * sum - 3 * j2; // e - e^eq
        const T dEps = (4 * f[0] - 2 * axis + diag) - sum + 3 * j2;
        const T dQx = (xDiag - 2 * d13) + px, dQy = (yDiag - 2 * d24) + py;
        const T dPxx = (a13 - a24) - (xx - yy), dPxy = (a57 - a68) - px * uy;
        T kP = T(-0.25 * sNu); // -s_nu / 4: the rate of pxx and pxy times their row of M^-1
        if constexpr (kLes) {
            // 2Q = 2 Pi_neq : Pi_neq = (de/3)^2 + dPxx^2 + 4 dPxy^2; s_nu / 4 = 1 / (2 (tau + R)).
            const T de3 = de * T(1.0 / 3), twoQ = de3 * de3 + dPxx * dPxx + 4 * dPxy * dPxy;
            const T r = std::sqrt(T(tau * tau) + T(c2x18) * std::sqrt(twoQ) * inv);
            kP = T(-0.5) / (T(tau) + r);
        }
        // The relaxed moments, each times its row of M^-1: a, b of e, eps; x, y of qx, qy.
        T a = T(-sE / 36) * de, b = T(-sEps / 36) * dEps;
        T x = T(-sQ / 12) * dQx, y = T(-sQ / 12) * dQy, p = kP * dPxx, s = kP * dPxy;
        T xAxis = -2 * x, yAxis = -2 * y; // the qx, qy share of the axis directions
        if constexpr (kForce) {
            // (I - S/2) M S^Guo: 6 u.F into e and -6 u.F into eps, F into j, -F into q,
            // 2 (ux Fx - uy Fy) into pxx and ux Fy + uy Fx into pxy.
            const T fxT = T(fx), fyT = T(fy), uf = ux * fxT + uy * fyT, kF = T(0.5) + kP;
            a += T((1 - 0.5 * sE) / 6) * uf;
            b -= T((1 - 0.5 * sEps) / 6) * uf;
            x -= T((1 - 0.5 * sQ) / 12 * fx);
            y -= T((1 - 0.5 * sQ) / 12 * fy);
            xAxis = T(fx / 6) - 2 * x;
            yAxis = T(fy / 6) - 2 * y;
            x += T(fx / 6);
            y += T(fy / 6);
            p += kF * (ux * fxT - uy * fyT);
            s += T(0.5) * kF * (ux * fyT + uy * fxT);
        }
        // f += M^T D dm, grouped by opposite pairs.
        const T axisE = -a - 2 * b, diagE = 2 * a + b;
        const T axisP = axisE + p, axisM = axisE - p, diagP = diagE + s, diagM = diagE - s;
        const T xPlusY = x + y, xMinusY = x - y;
        f[0] += 4 * (b - a);
        f[1] += axisP + xAxis;
        f[3] += axisP - xAxis;
        f[2] += axisM + yAxis;
        f[4] += axisM - yAxis;
        f[5] += diagP + xPlusY;
        f[7] += diagP - xPlusY;
        f[6] += diagM - xMinusY;
        f[8] += diagM + xMinusY;
    }
};

/// MRT without and with the LES shear rate, as operators of the force flag alone.
template <bool kForce> using MrtPlain = MrtCollision<false, kForce>;
template <bool kForce> using MrtWithLes = MrtCollision<true, kForce>;

/// visit(Op<true>{parameters...}) when `force`, else visit(Op<false>{parameters...}).
template <template <bool> class Op, class Visit, class... Parameters>
void withForceVariant(bool force, const Visit& visit, Parameters... parameters) {
    if (force)
        visit(Op<true>{parameters...});
    else
        visit(Op<false>{parameters...});
}

/// Call visit(collide) once with the operator of `params` and the body force (fx, fy) (Guo; the
/// force-free variants when both are 0): the one place the model and the force select a kernel,
/// shared by the bulk step and the partially saturated cells so that both collide alike. Each
/// branch instantiates visit for one concrete operator, so the node loop it runs is fully inlined.
template <class Visit>
void withCollision(const CollisionParams& params, Real fx, Real fy, const Visit& visit) {
    const CollisionParams& p = params;
    const bool force = fx != 0 || fy != 0;
    const Real sNu = 1.0 / p.tau, c2x18 = 18.0 * p.smagorinsky * p.smagorinsky;
    switch (p.model) {
    case CollisionModel::Bgk:
        withForceVariant<BgkCollision>(force, visit, sNu, fx, fy);
        break;
    case CollisionModel::Mrt:
        withForceVariant<MrtPlain>(force, visit, sNu, p.s_e, p.s_eps, p.s_q, p.tau, c2x18, fx, fy);
        break;
    case CollisionModel::MrtLes:
        withForceVariant<MrtWithLes>(force, visit, sNu, p.s_e, p.s_eps, p.s_q, p.tau, c2x18, fx,
                                     fy);
        break;
    }
}

} // namespace lbdem::solver::lattice
