// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file model_consistency.h
 *  \brief What a model read from a file must satisfy beyond its shapes, checked before it is used: a corrupt model
 *  (a bit flip, a scaled basis, a broken topology) is refused naming the part, never fitted as if it were sound.
 */
#include <morphreg/model/morphable_model.h>

#include <string>

namespace morphreg
{
/** \brief The largest coordinate magnitude of a model's mean accepted: 10^6 (a kilometre in mm): beyond it the file
 *  is corrupt, whatever its unit. */
constexpr double kMaxModelCoordinate = 1e6;

/** \brief Throws FormatError naming \a source and the part when \a model is inconsistent: a mean coordinate beyond
 *  kMaxModelCoordinate, a triangle that repeats a vertex, or a region basis or the global basis whose columns are
 *  not orthonormal (to 10^-3). (Landmark ids are checked where a file's format requires known ones.)
 *  \param[in] model the model as read
 *  \param[in] source the file, for the messages
 */
void
requireConsistentModel (const MorphableModel& model, const std::string& source);

/** \brief Throws FormatError naming \a source and the two datasets when two copies of a model's mean held in one file
 *  differ by more than their storage precision allows (float32: 10^-6 of the coordinate, at least 10^-5).
 *  \param[in] mean the copy used
 *  \param[in] copy another copy the file holds (interleaved x, y, z, like \a mean)
 *  \param[in] source the file, for the messages
 *  \param[in] names the two datasets, for the messages ("morphreg/mean and model/mean")
 */
void
requireSameMean (const Eigen::VectorXd& mean, const Eigen::VectorXd& copy, const std::string& source,
                 const std::string& names);

} // namespace morphreg
