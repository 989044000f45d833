#include <morphreg/common/error.h>
#include <morphreg/io/atomic_file.h>

#include <filesystem>

namespace morphreg
{
std::string
partialPath (const std::string& path)
{
  const std::filesystem::path target (path);
  return (target.parent_path () / (".partial." + target.filename ().string ())).string ();
}

void
commitPartial (const std::string& partial, const std::string& path)
{
  std::error_code ec;
  std::filesystem::rename (partial, path, ec);
  if (ec)
    throw IoError (path + ": cannot rename the finished " + partial + " onto it (" + ec.message () + ")");
}

} // namespace morphreg
