// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file model_description.h
 *  \brief What a model holds, as JSON (`morphreg model-info --json`, Python's Model.describe): its size, regions with
 *  their components and variances, the global PCA, landmarks, profile line, metadata and the unit of its file.
 */
#include <morphreg/model/morphable_model.h>

#include <nlohmann/json.hpp>

#include <string>

namespace morphreg
{
/** \brief The description of \a model: "file", "units", "file_units" (the unit the file was in before loadModel
 *  converted it; mm when it says none), "vertices", "triangles", "regions" (name, vertices, components,
 *  variances_mm2), "global_pca" (components, variances_mm2), "noise_variance_mm2", "profile_line_vertices",
 *  "landmarks" and "metadata".
 *  \param[in] model the model
 *  \param[in] file its file, as the description names it (empty for a model in memory)
 *  \return the description */
nlohmann::json
describeModel (const MorphableModel& model, const std::string& file = "");
} // namespace morphreg
