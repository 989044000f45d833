// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Expecting an error whose message says what and where (the file, line or option), as every morphreg error should.
#include <gtest/gtest.h>

#include <string>

namespace morphreg
{
namespace test
{
/** Expects \a call to throw E (or a subclass) with a message containing \a fragment. */
template <typename E, typename F>
void
expectErrorContaining (F call, const std::string& fragment)
{
  try {
    call ();
    ADD_FAILURE () << "no error; expected one containing '" << fragment << "'";
  }
  catch (const E& e) {
    EXPECT_NE (std::string (e.what ()).find (fragment), std::string::npos) << e.what ();
  }
}
} // namespace test
} // namespace morphreg
