// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Private to the glTF reader: tinygltf's API from Debian's tiny_gltf.h, its symbols hidden in libmorphreg_core, where
// tiny_gltf_implementation.cpp compiles its implementation (without stb_image: VTK's readers decode the textures).
//
// Debian's libtinygltf.so is not linked: libdraco.so.7 exports its own, older build of tinygltf's symbols (Draco's
// glTF support) with another class layout, and with both libraries loaded the dynamic linker serves every call from
// whichever it found first (seen: Draco's TinyGLTF::SetFsCallbacks writing where this header's TinyGLTF keeps a
// string, a heap corruption). Hidden symbols are bound inside libmorphreg_core, where neither library can shadow
// them. The headers tinygltf includes are included first, so that only tinygltf's own declarations are hidden.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#pragma GCC visibility push(hidden)
#include <tiny_gltf.h>
#pragma GCC visibility pop
