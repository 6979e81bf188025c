// D2Q9 velocity set and the TRT/BGK collision with Guo forcing, shared by the bulk kernel
// and the boundary path so both relax cells identically.
#pragma once

#include <array>
#include <cmath>

namespace hair25d::fluid::d2q9 {

// 0 rest, 1 +x, 2 +y, 3 -x, 4 -y, 5 (+x,+y), 6 (-x,+y), 7 (-x,-y), 8 (+x,-y).
inline constexpr std::array<int, 9> kCx = {0, 1, 0, -1, 0, 1, -1, -1, 1};
inline constexpr std::array<int, 9> kCy = {0, 0, 1, 0, -1, 1, 1, -1, -1};
inline constexpr std::array<int, 9> kOpp = {0, 3, 4, 1, 2, 7, 8, 5, 6};
inline constexpr std::array<double, 9> kW = {4.0 / 9,  1.0 / 9,  1.0 / 9,  1.0 / 9, 1.0 / 9,
                                             1.0 / 36, 1.0 / 36, 1.0 / 36, 1.0 / 36};

template <typename T>
struct Relaxation {
  T omega_plus;   // 1 / tau: relaxes the symmetric (viscous) part
  T omega_minus;  // relaxes the antisymmetric part; equal to omega_plus for BGK
  T gx, gy;       // body acceleration
  // Smagorinsky sub-grid model (only read when enabled): tau0 the molecular relaxation time,
  // les = 18 sqrt(2) C^2, magic the TRT Lambda, bgk = 1 for BGK (omega_minus = omega_plus).
  T tau0, les, magic, bgk;
};

// Populations are stored as deviations from the rest weights (f - w_i): sums of small numbers
// keep float round-off away from density 1. Relaxes `f` in place; returns |u|^2, whose sum
// over the grid is the divergence check (NaN and infinity propagate through it).
template <typename T, bool kForce, bool kLes = false>
[[gnu::always_inline]] inline T collide(T (&f)[9], const Relaxation<T>& r) {
  const T drho = f[0] + f[1] + f[2] + f[3] + f[4] + f[5] + f[6] + f[7] + f[8];
  const T rho = T(1) + drho;
  const T inv_rho = T(1) / rho;
  const T jx = f[1] - f[3] + f[5] - f[6] - f[7] + f[8];
  const T jy = f[2] - f[4] + f[5] + f[6] - f[7] - f[8];
  const T ux = jx * inv_rho + (kForce ? T(0.5) * r.gx : T(0));
  const T uy = jy * inv_rho + (kForce ? T(0.5) * r.gy : T(0));
  const T usq = ux * ux + uy * uy;
  // Smagorinsky (Hou et al. 1996): the eddy viscosity follows the local strain, read from the
  // non-equilibrium stress (deviations: sum c c f = P - I/3), so under-resolved shear (hair
  // tips, gusts) is damped instead of blowing up. All constants, no branches: the loop
  // around this must vectorise.
  const T pxx = f[1] + f[3] + f[5] + f[6] + f[7] + f[8] - rho * ux * ux - drho * T(1.0 / 3.0);
  const T pyy = f[2] + f[4] + f[5] + f[6] + f[7] + f[8] - rho * uy * uy - drho * T(1.0 / 3.0);
  const T pxy = f[5] - f[6] + f[7] - f[8] - rho * ux * uy;
  const T q = kLes ? std::sqrt(pxx * pxx + pyy * pyy + T(2) * pxy * pxy) : T(0);
  const T tau = kLes ? T(0.5) * (r.tau0 + std::sqrt(r.tau0 * r.tau0 + r.les * q * inv_rho)) : T(0);
  const T op = kLes ? T(1) / tau : r.omega_plus;
  // TRT keeps Lambda = (tau+ - 1/2)(tau- - 1/2) fixed; BGK (bgk = 1) relaxes both alike.
  const T om =
      !kLes ? r.omega_minus : r.bgk * op + (T(1) - r.bgk) / (T(0.5) + r.magic / (tau - T(0.5)));
  const T sym_base = drho - T(1.5) * rho * usq;  // w_i [drho + rho (4.5 cu^2 - 1.5 u^2)]
  const T fx = kForce ? rho * r.gx : T(0);
  const T fy = kForce ? rho * r.gy : T(0);
  const T uf = ux * fx + uy * fy;
  const T kp = T(1) - T(0.5) * op;
  const T km = T(1) - T(0.5) * om;
  {
    const T w0 = T(4.0 / 9.0);
    f[0] -= op * (f[0] - w0 * sym_base);
    if constexpr (kForce) f[0] -= kp * w0 * T(3) * uf;
  }
  // One pair (i, opposite j) with c_i = (cx, cy): symmetric and antisymmetric parts relax apart.
  auto pair = [&](int i, int j, T w, T cu, T cf) {
    const T eq_sym = w * (sym_base + T(4.5) * rho * cu * cu);
    const T eq_anti = w * T(3) * rho * cu;
    const T ns = op * (T(0.5) * (f[i] + f[j]) - eq_sym);
    const T na = om * (T(0.5) * (f[i] - f[j]) - eq_anti);
    T ss = T(0), sa = T(0);
    if constexpr (kForce) {
      ss = kp * w * (T(9) * cu * cf - T(3) * uf);
      sa = km * w * T(3) * cf;
    }
    f[i] += -ns - na + ss + sa;
    f[j] += -ns + na + ss - sa;
  };
  const T ws = T(1.0 / 9.0);
  const T wd = T(1.0 / 36.0);
  pair(1, 3, ws, ux, fx);
  pair(2, 4, ws, uy, fy);
  pair(5, 7, wd, ux + uy, fx + fy);
  pair(6, 8, wd, uy - ux, fy - fx);
  return usq;
}

// Equilibrium deviations f_eq - w for density rho and velocity (ux, uy).
template <typename T>
inline void equilibrium(T rho, T ux, T uy, T (&f)[9]) {
  const T usq = ux * ux + uy * uy;
  for (int i = 0; i < 9; ++i) {
    const T cu = T(kCx[i]) * ux + T(kCy[i]) * uy;
    const T w = T(kW[i]);
    f[i] = w * (rho - T(1)) + w * rho * (T(3) * cu + T(4.5) * cu * cu - T(1.5) * usq);
  }
}

}  // namespace hair25d::fluid::d2q9
