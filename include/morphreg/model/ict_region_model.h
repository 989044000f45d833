// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file ict_region_model.h
 *  \brief The thesis's 7-region model built from the ICT-FaceKit head model, which ships no region labels.
 *
 *  Recipe (what buildIctRegionModel does):
 *  1. load the global ICT model (loadIctFaceKit, in mm);
 *  2. segment its mean mesh into eyes, nose, mouth, ears, chin, cheeks and skull_neck with
 *     segmentByLandmarkGroups and the groups of ictRegionGroups (geodesic radii around landmark seeds);
 *  3. draw a few hundred heads from the ICT distribution (coefficients ~ N(0, variances));
 *  4. run ModelBuilder on them with those regions.
 *
 *  \code
 *  auto ict = morphreg::loadIctFaceKit ("ict_facekit") // the ICT-FaceKit folder;
 *  auto regional = morphreg::buildIctRegionModel (*ict, 300, 1);
 *  morphreg::saveModel ("ict_7_regions.h5", *regional);
 *  \endcode
 */
#include <morphreg/model/model_builder.h>
#include <morphreg/model/region_segmentation.h>

#include <cstdint>

namespace morphreg
{
/** \brief Seeds and geodesic radii (mm) of the six face regions on an ICT model loaded by loadIctFaceKit (needs
 *  its ibug68_* and tragus landmarks); the cheek seeds are the vertices nearest to the centroid of outer eye
 *  corner, mouth corner and jaw contour point on each side.
 *  \param[in] ict the ICT model as loaded
 *  \return one group per face region
 */
std::vector<LandmarkGroup>
ictRegionGroups (const MorphableModel& ict);

/** \brief Samples \a samples heads from \a ict (seeded by \a seed) and builds the 7-region model with
 *  \a settings; landmarks, profile line and units are carried over.
 *  \param[in] ict the ICT model as loaded
 *  \param[in] samples how many heads to draw from it
 *  \param[in] seed the random seed of the draw
 *  \param[in] settings the model builder's settings
 *  \return the 7-region model
 */

MorphableModel::Ptr
buildIctRegionModel (const MorphableModel& ict, int samples, std::uint64_t seed,
                     const ModelBuilderSettings& settings = {});

} // namespace morphreg
