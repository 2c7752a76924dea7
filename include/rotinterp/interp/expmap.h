// expmap: cubic spline of the keys' rotation vectors (Grassia 1998, §4.2).
//
// Every key is logged with the nearest-branch log (each key's preimage nearest the
// previous key's vector: core log_nearest), so that spins past π and 2π do not
// jump; a cubic spline is fitted per coordinate in R³ and mapped back with exp.
// Coordinate-DEPENDENT by nature: the curve depends on where the identity is, so
// left/right multiplying the keys does not transform it alike (the contract test
// records by how much). Exact for a constant-rate spin that starts at the identity
// (v(t) = ω·t is linear), even past 2π — only with the unwrapping.
#pragma once

#include "rotinterp/track/track.h"
#include "rotinterp/core/result.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/interp/interpolator.h"

#include <memory>

namespace rotinterp {

struct ExpmapOptions {
  enum class Spline {
    // Hermite with tangents (vₖ₊₁ − vₖ₋₁)/(tₖ₊₁ − tₖ₋₁), one-sided at the ends: C¹,
    // local (a key moves only 4 segments). Registry name "expmap".
    catmull_rom,
    // Natural cubic spline (v″ = 0 at the ends): C², global. Registry name "expmap-c2".
    natural,
  };
  Spline spline = Spline::catmull_rom;
  // Nearest-branch logs (default). false takes each key's principal log (|v| ≤ π):
  // only for demonstrating why unwrapping is needed — the curve then jumps.
  bool unwrap = true;
  // Take the rotation vectors relative to the keys' BF mean m (vₖ from m⁻¹qₖ, curve
  // m·exp(v(t))): keeps |v| small for tracks that stay near an orientation far
  // from the identity. Falls back to the chordal mean when the BF mean fails.
  bool relative_to_mean = false;
};

Result<std::unique_ptr<Interpolator>> make_expmap(RotationTrack track, const ExpmapOptions& options = {});

}  // namespace rotinterp
