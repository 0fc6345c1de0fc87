#pragma once

// The points' weights as the maximum-likelihood solvers ("joint", "lm") take them: a weight is
// the inverse of its point's variance only up to a few times the median
// (SolverOptions::max_weight_ratio); the strongest edge points beside a junction are more often a
// second edge than a better-placed point of it.

#include "corridor_depth/corridor_observation.h"

namespace corridor {

// *capped = observation with each side's weights at most max_ratio times that side's median
// weight, then scaled to a mean of 1 on each side. False, writing nothing, when the observation
// has no weights or max_ratio is 0 (the weights are taken as given).
bool CapWeights(const CorridorObservation& observation, double max_ratio,
                CorridorObservation* capped);

}  // namespace corridor
