// The numeric axes of eval's plots and the texts on them, computed without PLplot so
// that what is drawn can be checked from its numbers (eval/plot_layout.h).
#pragma once

#include <string>
#include <vector>

namespace rotinterp {

// Angles below this (degrees) are zero to round-off: a log axis does not stretch to
// them (a method that reproduces a still clip gives 1e-14°, fifteen decades below
// the rest); they are drawn as open markers on its bottom edge.
constexpr double kZeroDeg = 1e-9;
// Angles stop at 180°: an angle axis ends there, plus the margin that keeps a
// marker at 180° inside the frame.
constexpr double kMaxDeg = 180.0;
// Room kept between the values and each end of an axis: a fraction of its span,
// so that no marker sits on (and is cut by) the frame.
constexpr double kAxisPad = 0.05;
// The narrowest axis: values nearer each other than this get an axis of this span
// around them. Log axes in decades (0.46 %), linear ones as a fraction of the value.
constexpr double kMinLogSpan = 0.002, kMinLinearSpan = 0.01;
// Fewest labelled ticks on a numeric axis: one or two ticks give no scale.
constexpr int kMinTicks = 3;

struct PlotTick {
  double at;          // in axis units: log₁₀ (log₂ for key spacings) on a log axis
  std::string label;  // the value, in degrees (or frames)
};

// An axis as drawn. Units: log₁₀ degrees when `log`, else degrees; a key-spacing axis
// is log₂ frames.
struct PlotAxis {
  bool log = false;
  double lo = 0, hi = 1;          // the drawn range
  double data_lo = 0, data_hi = 0;  // the values' extent (zeros on a log axis: at lo)
  bool any = false;               // some value above kZeroDeg
  std::vector<PlotTick> ticks;    // labelled, inside [lo, hi], ascending
};

// How an angle axis chooses its scale: always log (error against spacing, whose
// slopes are the orders of the methods), or log only where the values span a decade
// or more and otherwise linear (from 0 when the smallest is under half the largest).
enum class AxisScale { log, automatic };

// The axis of `deg` (non-finite values ignored): the values' extent padded by kAxisPad,
// ending within the pad above 180°, with at least kMinTicks labelled ticks (decades;
// 1-2-5 within a decade; else evenly spaced round values: 100, 120, … 180). All zero:
// linear, 0 to 1.
PlotAxis angle_axis(const std::vector<double>& deg, AxisScale scale);

// The log₂ axis of key spacings N: ticks at powers of two, widened to at least
// kMinTicks of them.
PlotAxis spacing_axis(const std::vector<int>& keep_every);

// Characters in `text` (UTF-8 code points).
std::size_t text_chars(const std::string& text);

// `text` shortened to `max_chars` characters by an ellipsis in the middle, keeping
// both ends ("LeftUpL…Thumb2"); unchanged when it fits.
std::string middle_ellipsis(const std::string& text, std::size_t max_chars);

// Each name middle-shortened to `max_chars`, lengthening any that would read the same
// as another until none do (equal names stay equal only where the names are).
std::vector<std::string> short_labels(const std::vector<std::string>& names, std::size_t max_chars);

// The file name of a clip id ("DIR/walk.bvh" or "DIR/file.fbx#take"), never its
// directories; `clip_labels` adds parent directories only where two names would
// otherwise read the same.
std::string clip_file_name(const std::string& clip);
std::vector<std::string> clip_labels(const std::vector<std::string>& clips);

}  // namespace rotinterp
