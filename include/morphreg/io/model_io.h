// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file model_io.h
 *  \brief MorphableModel files: HDF5 in the statismo v0.9 layout (readable by statismo/scalismo tools as a
 *  global PCA model) plus a /morphreg group with the regions, blending weights, per-region bases, landmarks and
 *  profile line.
 *
 *  Statismo part (float32, row-major): /model/mean [3N] interleaved x,y,z; /model/pcaBasis [3N, k] orthonormal
 *  columns; /model/pcaVariance [k]; /model/noiseVariance scalar; /representer/points [3, N] (the mean shape);
 *  /representer/cells [3, M] int32; /representer attributes name, datasetType = "POLYGON_MESH";
 *  /version/majorVersion = 0, minorVersion = 9; /modelinfo/build-time, /modelinfo/scores [k, 0] (no scores kept).
 *
 *  morphreg part (float64 so a round trip is exact): /morphreg/formatVersion = 1; mean [3N]; units; landmarks and
 *  metadata (JSON strings); profileLine [L] int32; numRegions; regions/region_\<j\>/{name, vertices [B] int32,
 *  weights [B], basis [3B, P], variances [P]}.
 */
#include <morphreg/model/morphable_model.h>

#include <string>

namespace morphreg
{
/** \brief The metadata key under which loadModel and loadStatismoModel record the file's unit and how it is known,
 *  e.g. "mm (the file's units)" or "m (guessed from its size: ...); converted to mm on loading". */
constexpr const char* kFileUnitsKey = "file_units";

/** \brief Writes \a model to \a path (HDF5, usually .h5), whole or not at all (a temporary file renamed when
 *  complete); throws IoError naming the file on failure.
 *  \param[in] path the model file
 *  \param[in] model the model to write
 */
void
saveModel (const std::string& path, const MorphableModel& model);

/** \brief Loads a model file: the full multi-region model if the file has a /morphreg group, otherwise the
 *  statismo-layout global PCA model found at the root or under the Basel Face Model 2017 prefix "shape/".
 *  The model is returned in mm whatever the file's unit: a morphreg file states it (/morphreg/units: mm, cm, dm, m
 *  or in), a statismo file does not, so its unit is guessed from the mean's size (guessModelUnit: a model in m or cm
 *  is recognised); coordinates are converted, variances by the square, and metadata()[kFileUnitsKey] says what was
 *  found and done. Throws IoError for a missing file, FormatError naming the file, the dataset and the problem for
 *  anything corrupt (missing dataset, wrong dimensions, non-finite values, out-of-range indices, truncated file), a
 *  units dataset that names no length unit, or a statismo model whose size fits no unit (e.g. micrometres).
 *  \param[in] path the model file
 *  \return the model
 */
MorphableModel::Ptr
loadModel (const std::string& path);

/** \brief Loads the statismo-layout model under \a prefix ("" for the root, "shape" for BFM-2017 files).
 *  statismo v0.8 files (minorVersion 8) store the basis scaled by the standard deviations; it is normalised on
 *  import. A file without a version group is read as v0.9. The unit is guessed from the mean's size and the model
 *  converted to mm (as loadModel). The
 *  landmarks of a BFM-2017 file's metadata/landmarks/json (scalismo's layout, ids translated by
 *  fromBfmLandmarkId()) become the model's, each on the mean vertex nearest to it.
 *  \param[in] path the model file
 *  \param[in] prefix the HDF5 group holding the model
 *  \return a one-region model
 */

MorphableModel::Ptr
loadStatismoModel (const std::string& path, const std::string& prefix = "");

} // namespace morphreg
