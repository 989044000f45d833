// SPDX-License-Identifier: BSD-3-Clause
// Fuzz targets landmarks_<format>: the 3D landmark, named point and pixel landmark loaders on each landmark file
// format (PickedPoints files hold 3D points only).
#include "fuzz_target.h"

#include <morphreg/io/landmark_io.h>

namespace
{
using morphreg::fuzz::Loader;

const Loader load_landmarks = [] (const std::string& path) { morphreg::loadLandmarks (path); };
const Loader load_named_points = [] (const std::string& path) { morphreg::loadNamedPoints (path); };
const Loader load_pixels = [] (const std::string& path) { morphreg::loadLandmarkPixels (path); };

const bool registered =
    morphreg::fuzz::registerTarget ({"landmarks_pp", ".pp", {load_landmarks, load_named_points}}) &&
    morphreg::fuzz::registerTarget ({"landmarks_json", ".json", {load_landmarks, load_named_points, load_pixels}}) &&
    morphreg::fuzz::registerTarget ({"landmarks_csv", ".csv", {load_landmarks, load_named_points, load_pixels}}) &&
    morphreg::fuzz::registerTarget ({"landmarks_pts", ".pts", {load_landmarks, load_named_points, load_pixels}});
} // namespace
