// Limits the solver and the units helper refuse to go past, in lattice units.
#pragma once

namespace hair25d::fluid {

// BGK needs a margin above 1/2; TRT with Lambda = 1/4 stays linearly stable much closer.
inline constexpr double kMinTauBgk = 0.505;
inline constexpr double kMinTauTrt = 0.5001;
inline constexpr double kMaxTau = 5.0;
inline constexpr int kMaxGridSide = 16384;
inline constexpr double kMaxGridCells = 16.0 * 1024 * 1024;
inline constexpr double kMaxBodyAcceleration = 1e-2;
inline constexpr int kMaxObstacles = 100000;
// Without a sub-grid model: cell Reynolds number (peak speed / viscosity, lattice units)
// above which gusty wind through a comb of hair filaments blew up in our runs (TRT stable at
// 8, diverged at 16; BGK stable down to its tau limit; see docs/fluid.md).
inline constexpr double kMaxCellReynoldsBgk = 30.0;
inline constexpr double kMaxCellReynoldsTrt = 10.0;

}  // namespace hair25d::fluid
