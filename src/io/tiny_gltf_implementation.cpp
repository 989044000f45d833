// SPDX-License-Identifier: BSD-3-Clause
// tinygltf's implementation, compiled from Debian's header into libmorphreg_core with hidden symbols (see
// tiny_gltf_hidden.h for why not Debian's libtinygltf.so).
#define TINYGLTF_IMPLEMENTATION
#include "tiny_gltf_hidden.h"
