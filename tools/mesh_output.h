// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What a mesh written by a subcommand carries, in the words of its "wrote ..." line: only what the --out format keeps.
#include <string>

namespace morphreg
{
namespace tools
{
/** \brief "(vertex colours: <colours>; vertex quality: <quality>)" for a mesh written to \a path whose colours show
 *  \a colours and whose "quality" field holds \a quality (empty: it has none), saying only what the format keeps
 *  (savedVertexData): an OBJ names its colour syntax and says where the values went missing.
 *  \param[in] path the mesh file (.ply, .obj or .vtk)
 *  \param[in] colours what the colours show, e.g. "residual, 0-5 mm"
 *  \param[in] quality what the quality scalar holds, e.g. "residual in mm"; empty for none
 *  \return the parenthesis
 */
std::string
meshContents (const std::string& path, const std::string& colours, const std::string& quality);

/** \brief The --out help of a subcommand writing such a mesh: the formats and what each keeps.
 *  \param[in] what the mesh, e.g. "fitted mesh to write"
 *  \param[in] colours what the colours show
 *  \param[in] quality what the quality scalar holds; empty for none
 *  \return the help text
 */
std::string
meshOutputHelp (const std::string& what, const std::string& colours, const std::string& quality);
} // namespace tools
} // namespace morphreg
