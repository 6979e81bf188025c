// The bar the layering and completion share for an `equal` the same-depth
// model is sure of.
#pragma once

namespace hair25d {

// An `equal` whose same-depth mean log-odds over its occluding boundaries
// (EqualEvidence::log_odds, not open) is over this is firm: the layering
// sets it before the orders, which would otherwise override it, and
// completion trusts it even between pieces painted apart. One constant, so
// that what the layering calls sure and what completion trusts stay one bar.
inline constexpr double kFirmEqualLogOdds = 2.0;

}  // namespace hair25d
