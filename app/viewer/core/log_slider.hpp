#pragma once
// A logarithmic slider's mapping, for ranges spanning decades (the shininess s from 1 to 1000):
// equal slider travel multiplies the value by equal factors, so 1 → 10 takes as much drag as
// 100 → 1000. Values outside the range (typed) sit at the ends of the slider and are kept.

namespace facet::view {

/// The slider position in [0, 1] of `value` on a log scale from `min` to `max` (both > 0,
/// min < max); values at or below `min` give 0, at or above `max` give 1, NaN gives 0.
double logSliderPosition(double value, double min, double max);

/// The value at slider position `t` (clamped to [0, 1]): min · (max / min)^t.
double logSliderValue(double t, double min, double max);

/// The value rounded to `digits` significant digits (what the slider's text shows and what a
/// drag lands on, so a drag does not leave 29.99731 behind).
double roundSignificant(double value, int digits);

}  // namespace facet::view
