// How a method is drawn wherever it is shown: eval's plots and render's panels.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace rotinterp {

// A method's colour, marker and dash follow its place in the registry (methods()), so
// one method looks the same in every plot and image, whatever else is compared with it.
struct MethodStyle {
  std::array<std::uint8_t, 3> rgb;  // sRGB: readable on a white page and on render's dark grey
  const char* marker;               // filled (a UTF-8 glyph)
  const char* open_marker;          // its open form: a zero on a log axis
  int dash;                         // 1…8: PLplot's line styles
};

// One style per registered method, in registry order: Okabe–Ito's colour-blind-safe
// colours (grey for its black, lost on a dark background; no yellow, lost on white), then
// Paul Tol's rose and olive.
constexpr std::size_t kMethodStyles = 9;

// The style of `slot`, modulo kMethodStyles.
const MethodStyle& method_style(std::size_t slot);

// A method's slot: its place in methods() (any case); an unknown name takes the first
// slot after them.
std::size_t method_slot(std::string_view name);

}  // namespace rotinterp
