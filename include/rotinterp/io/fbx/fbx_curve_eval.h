// FBX curves evaluated as the DCC (Maya, MotionBuilder, the FBX SDK) does, from
// the stored keys (io/fbx/fbx_curves.h):
//  * constant keys hold their value (constant-next: the next key's);
//  * linear keys interpolate linearly;
//  * cubic keys are a Bezier segment whose inner control points lie at the
//    tangent weights (1/3 of the segment unless weighted) along time, on the stored
//    slopes; time → parameter is solved (exact for unweighted keys, where the
//    Bezier is the cubic Hermite of the slopes);
//  * before the first and after the last key, the curve's extrapolation:
//    constant, repetition, mirror repetition, or keep-slope.
// Times in FBX ticks, as doubles so that samples may fall between ticks.
#pragma once

#include "rotinterp/io/fbx/fbx_curves.h"

#include <cstddef>
#include <vector>

namespace rotinterp {

// A key's tangents as the DCC evaluates them: slopes in value per second, weights
// as fractions of the adjacent segment. User and broken keys keep their stored
// slopes; auto, spline and clamped keys are solved from their neighbours (the
// stored auto bias bending them); TCB keys from tension, continuity and bias;
// constant and linear segments give flat and secant tangents. The left tangent of
// a key comes from the previous key's stored next-left slope unless the key itself
// solves it.
struct FbxKeyTangents {
  double left_slope = 0.0, left_weight = 1.0 / 3.0;
  double right_slope = 0.0, right_weight = 1.0 / 3.0;
};
FbxKeyTangents fbx_key_tangents(const std::vector<FbxKey>& keys, std::size_t i);

// The curve's value at `ticks`; its default value when it has no key. Finite.
double evaluate_fbx_curve(const FbxCurve& curve, double ticks);

// The curve at k/hz seconds for k = 0, 1, … while k/hz ≤ end_ticks (FBX time 0 is
// t = 0). hz > 0.
std::vector<double> sample_fbx_curve(const FbxCurve& curve, double hz, std::int64_t end_ticks);
// How many samples that gives (about: the last may fall either side of the end), as a
// double so that a huge rate does not wrap; 0 where hz is not > 0 or NaN.
double fbx_sample_count(double hz, std::int64_t end_ticks);

}  // namespace rotinterp
