// bf's knots (not installed): make_bf (interp/bf.h) solves a BF spline through the
// keys where it can, and through the keys and in-between knots where neighbouring
// keys are too far apart (BfSplineOptions::max_key_step) or one interval is much
// longer than the next (bf_knots.cpp, grading).
#pragma once

#include "detail.h"

namespace rotinterp::detail {

// `k` with in-between knots wherever neighbours are more than max_step apart, and
// wherever an interval is more than 1.5·kGrading times a neighbouring one. Every
// in-between knot lies on `along`, the c2 curve through the original keys: a C²
// curve accurate to h⁴, so the spline keeps its accuracy on wide steps (on the
// geodesic, wide segments were no better than slerp); c2 is bi-invariant and
// exact on constant angular velocity, so the spline stays so too.
Keys refine_bf_knots(const Keys& k, double max_step, const Interpolator& along);
// Whether some interval of `k` is graded by refine_bf_knots.
bool bf_knots_need_grading(const Keys& k);
// Whether refine_bf_knots would insert any knot.
bool bf_knots_need_refinement(const Keys& k, double max_step);

}  // namespace rotinterp::detail
