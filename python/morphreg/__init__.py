# SPDX-License-Identifier: BSD-3-Clause
"""morphreg: morphable-model registration and thin plate spline warping for point clouds (C++ on PCL).

Points are (N, 3) float64 or float32 numpy arrays in millimetres; results are float64 arrays. Every
error is a morphreg.Error (InvalidInputError is also a ValueError, IoError an OSError).
"""
from ._morphreg import *  # noqa: F401,F403
from ._morphreg import __version__  # noqa: F401
from ._morphreg import _photo_fit_options, _registration_options, _resampling_options  # noqa: F401  (the settings tables)
