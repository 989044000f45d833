// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/photo/shape_prior_selection.h>

#include <cmath>
#include <map>

namespace morphreg
{
const std::vector<double>&
ShapePriorSelection::multiples ()
{
  static const std::vector<double> values = {1.0, 3.0, 10.0, 30.0};
  return values;
}

ShapePriorSelection::ShapePriorSelection (double landmark_noise) : noise_ (landmark_noise)
{
  if (!(landmark_noise > 0.0) || !std::isfinite (landmark_noise))
    throw InvalidInputError ("PhotoFitting: the landmark noise must be finite and > 0 pixels, got " +
                             std::to_string (landmark_noise));
}

std::vector<std::vector<bool>>
ShapePriorSelection::folds (const MultiViewProblem& problem, PhotoRows rows) const
{
  const std::vector<int> vertices = problem.landmarkVertices ();
  if (rows == PhotoRows::outlines)
    return {std::vector<bool> (vertices.size (), true)}; // the fit uses no landmark: all of them validate it
  // Each fold is a run of landmarks in the order they are first marked (the order of their ids: a region of the
  // face, such as the brows or the mouth), so a fold's fits predict a region the photos' other landmarks do not
  // pin down, not points between fitted neighbours that any flexible shape interpolates.
  std::map<int, size_t> order; // model vertex -> its place among the vertices, in the order first marked
  for (const int vertex : vertices)
    order.emplace (vertex, order.size ());
  const size_t count = std::min<size_t> (kFolds, order.size ());
  std::vector<std::vector<bool>> folds (count, std::vector<bool> (vertices.size (), false));
  for (size_t l = 0; l < vertices.size (); ++l)
    folds[order.at (vertices[l]) * count / order.size ()][l] = true;
  return folds;
}

ShapePriorChoice
ShapePriorSelection::choose (MultiViewProblem& problem, PhotoRows rows) const
{
  const PoseShapeState start = problem.initialState ();
  double mm_per_pixel = 0.0;
  for (size_t v = 0; v < problem.numViews (); ++v)
    mm_per_pixel += problem.millimetresPerPixel (v, start) / static_cast<double> (problem.numViews ());
  ShapePriorChoice choice;
  choice.noise_weight = noise_ * mm_per_pixel;
  if (problem.numLandmarks () < kMinimumLandmarks) {
    choice.weight = kDefaultMultiple * choice.noise_weight;
    choice.rule = "noise";
    problem.setPriorWeight (choice.weight);
    return choice;
  }
  const std::vector<double>& factors = multiples ();
  std::vector<double> squares (factors.size (), 0.0);
  double mean_squares = 0.0, count = 0.0;
  for (const std::vector<bool>& left_out : folds (problem, rows)) {
    const double held = static_cast<double> (std::count (left_out.begin (), left_out.end (), true));
    std::vector<PhotoFitIteration> history;
    PoseShapeState posed = start;
    problem.poseStage (posed, rows, left_out, history);
    mean_squares += std::pow (problem.landmarkError (posed, left_out), 2) * held;
    for (size_t k = 0; k < factors.size (); ++k) {
      problem.setPriorWeight (factors[k] * choice.noise_weight);
      PoseShapeState fitted = posed;
      problem.shapeStages (fitted, rows, left_out, history, kIterations);
      squares[k] += std::pow (problem.landmarkError (fitted, left_out), 2) * held;
    }
    count += held;
  }
  size_t best = 0;
  for (size_t k = 0; k < factors.size (); ++k) {
    choice.candidates.push_back ({factors[k] * choice.noise_weight, std::sqrt (squares[k] / count)});
    best = squares[k] < squares[best] ? k : best;
  }
  choice.mean_head_error_mm = std::sqrt (mean_squares / count);
  choice.beats_mean_head = std::sqrt (squares[best]) < (1.0 - kMinimumGain) * std::sqrt (mean_squares);
  choice.weight = (choice.beats_mean_head ? factors[best] : kNearMean) * choice.noise_weight;
  choice.rule = "left-out landmarks";
  problem.setPriorWeight (choice.weight);
  return choice;
}
} // namespace morphreg
