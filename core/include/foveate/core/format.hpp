#pragma once
// Numbers written for people to read in reports, charts and the viewer: a
// few significant digits, never a raw double ("0.00683761") nor printf's
// exponent ("2.67701e-05"). CSV and JSON keep full precision; these are for
// what is read, not parsed back.
#include <string>

namespace foveate {

/// `value` to `digits` significant digits (at least 1), trailing zeros kept
/// since they are significant: 0.00683761 -> "0.00684", 1 -> "1.00",
/// 13.333 -> "13.3". A value with more integer digits than `digits` is
/// rounded to a whole number (2073600 -> "2073600", never an exponent); one
/// under 0.001 is written with a power of ten: 2.67701e-05 -> "2.68×10⁻⁵".
/// 0 -> "0"; NaN -> "–" (not measured); infinities -> "∞", "−∞".
std::string format_significant(double value, int digits = 3);

/// format_significant with a unit after a space: "2.05 ms", "45.3 %"; the
/// unit is left out for NaN ("–").
std::string format_quantity(double value, const std::string& unit, int digits = 3);

/// A share (0..1) as a percentage with `digits` significant digits: 0.453 ->
/// "45.3 %", 0.00012 -> "0.0120 %"; an exact 0 -> "0 %". Small but nonzero
/// shares never print as "0.0 %".
std::string format_percent(double share, int digits = 3);

/// A tick label of an axis whose ticks are `step` apart: as many decimals as
/// the step needs and no more (step 0.05: 0.1 -> "0.10"; step 5: 10 -> "10"),
/// and a power of ten when the step is under 0.001 (step 1e-5: 2e-5 ->
/// "2×10⁻⁵").
std::string format_tick(double value, double step);

/// 10 to the power `exponent` as a log axis labels it: written out from 0.01
/// to 1000 ("0.01", "1000"), as a power beyond ("10⁶", "10⁻³").
std::string format_power_of_ten(int exponent);

}  // namespace foveate
