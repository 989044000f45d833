# SPDX-License-Identifier: BSD-3-Clause
# The TPS tests compare against VTK's vtkThinPlateSplineTransform (found through PCL's VTK).
target_link_libraries(${target} PRIVATE VTK::CommonCore VTK::CommonTransforms)
