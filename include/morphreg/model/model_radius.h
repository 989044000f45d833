// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file model_radius.h
 *  \brief The size of a model's mean head, which a scan's size is compared with to tell its length unit.
 */
#include <morphreg/model/morphable_model.h>

namespace morphreg
{
/** \brief The RMS distance of \a model's mean vertices from their centroid (mm): the size guessLengthUnit compares
 *  a scan with.
 *  \param[in] model the model
 *  \return its RMS radius (mm)
 */
double
modelRadius (const MorphableModel& model);
} // namespace morphreg
