// The colour map of error-coloured poses: viridis, a perceptually uniform map
// (lightness rises steadily from dark purple through teal to yellow, and it reads
// the same to the common colour-vision deficiencies), and the error scale its
// colour bar states.
#pragma once

#include "rotinterp/render/renderer.h"

namespace rotinterp::render {

// viridis at t ∈ [0, 1] (clamped; NaN gives the colour of 0): piecewise linear
// through 33 of the 256 published entries (every 8th, and the last), within
// 1.7/255 of the full table everywhere. sRGB display values 0…1.
Colour viridis(double t);

// The colour bar's top, degrees: the smallest 1-2-5 step (…, 0.5, 1, 2, 5, 10, …)
// at or above `max_error_deg`, at least 1° (a frame whose worst error is tiny —
// a key — does not blow noise up to the whole map) and at most 180° (angles stop
// there: 200 would leave the bar's top unused). Non-finite input gives 1.
double error_scale(double max_error_deg);

// The colour of `error_deg` on a bar from 0 to `scale_deg`.
Colour error_colour(double error_deg, double scale_deg);

}  // namespace rotinterp::render
