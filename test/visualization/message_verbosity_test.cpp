// SPDX-License-Identifier: BSD-3-Clause
// How much PCL and VTK say (message_verbosity.h): VTK's errors held at the normal level, dropped when quiet.
#include <morphreg/visualization/message_verbosity.h>

#include <pcl/console/print.h>

#include <vtkPNGReader.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

namespace
{
/** A VTK error: a PNG reader on a file that is not there. */
void
causeVtkError ()
{
  auto reader = vtkSmartPointer<vtkPNGReader>::New ();
  reader->SetFileName ("/no/such/folder/picture.png");
  reader->Update ();
}

TEST (MessageVerbosityTest, VtkErrorsAreHeldAtTheNormalLevelAndDroppedWhenQuiet)
{
  morphreg::setMessageVerbosity (morphreg::MessageVerbosity::normal);
  morphreg::takeHeldVtkErrors ();
  EXPECT_EQ (pcl::console::getVerbosityLevel (), pcl::console::L_ERROR);
  causeVtkError ();
  EXPECT_FALSE (morphreg::takeHeldVtkErrors ().empty ()) << "held at the normal level";
  EXPECT_TRUE (morphreg::takeHeldVtkErrors ().empty ()) << "taken once";

  morphreg::setMessageVerbosity (morphreg::MessageVerbosity::quiet);
  EXPECT_EQ (pcl::console::getVerbosityLevel (), pcl::console::L_ALWAYS);
  causeVtkError ();
  EXPECT_TRUE (morphreg::takeHeldVtkErrors ().empty ()) << "dropped when quiet";

  morphreg::setMessageVerbosity (morphreg::MessageVerbosity::verbose);
  EXPECT_EQ (pcl::console::getVerbosityLevel (), pcl::console::L_DEBUG);
  morphreg::setMessageVerbosity (morphreg::MessageVerbosity::normal);
}
} // namespace
