// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file registration_options.h
 *  \brief The one table of the registration settings a user can set (RegistrationSettings): name, help text, range or
 *  choices. The command line (`--max-distance`), the Python keywords (`max_distance=`) and requireValidSettings all
 *  read it, so a setting is named, explained and bounded once.
 */
#include <morphreg/common/setting_options.h>
#include <morphreg/registration/registration_settings.h>

#include <string>
#include <vector>

namespace morphreg
{
/** \brief One setting of RegistrationSettings as users set it. */
using RegistrationOption = SettingOption<RegistrationSettings>;

/** \brief Every user setting of a registration.
 *  \return the table, in the order --help lists it */
const std::vector<RegistrationOption>&
registrationOptions ();

/** \brief The option of a setting.
 *  \param[in] name the setting's (field's) name
 *  \return the option, or nullptr if there is none */
const RegistrationOption*
findRegistrationOption (const std::string& name);

} // namespace morphreg
