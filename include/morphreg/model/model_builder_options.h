// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file model_builder_options.h
 *  \brief The one table of ModelBuilder's settings a user sets: name, help text and range. `morphreg build-model`
 *  (--components, --variance, --blend-rings, --no-procrustes), Python's Model.build keywords and ModelBuilder's own
 *  check read it.
 */
#include <morphreg/common/setting_options.h>
#include <morphreg/model/model_builder.h>

#include <vector>

namespace morphreg
{
/** \brief One setting of ModelBuilderSettings as users set it. */
using ModelBuilderOption = SettingOption<ModelBuilderSettings>;

/** \brief Every user setting of a model building's PCA (the PCA method is chosen by size, not by users).
 *  \return the table, in the order --help lists it */
const std::vector<ModelBuilderOption>&
modelBuilderOptions ();
} // namespace morphreg
