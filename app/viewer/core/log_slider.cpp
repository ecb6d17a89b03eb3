#include "log_slider.hpp"

#include <algorithm>
#include <cmath>

namespace facet::view {

double logSliderPosition(double value, double min, double max) {
    if (!(value > min) || !(max > min) || !(min > 0.0)) return 0.0;
    if (value >= max) return 1.0;
    return std::log(value / min) / std::log(max / min);
}

double logSliderValue(double t, double min, double max) {
    if (!(t > 0.0)) return min;
    if (t >= 1.0) return max;
    return min * std::pow(max / min, t);
}

double roundSignificant(double value, int digits) {
    if (value == 0.0 || !std::isfinite(value) || digits <= 0) return value;
    const double magnitude = std::floor(std::log10(std::abs(value)));
    const double step = std::pow(10.0, magnitude - (digits - 1));
    return std::round(value / step) * step;
}

}  // namespace facet::view
