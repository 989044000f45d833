// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/io/file_fingerprint.h>

#include <morphreg/common/error.h>

#include <filesystem>
#include <fstream>
#include <vector>

namespace morphreg
{
void
Fnv1a64::add (const char* bytes, std::size_t count)
{
  constexpr std::uint64_t kPrime = 0x100000001b3ULL;
  std::uint64_t state = state_;
  for (std::size_t i = 0; i < count; ++i)
    state = (state ^ static_cast<unsigned char> (bytes[i])) * kPrime;
  state_ = state;
}

std::string
Fnv1a64::hex () const
{
  static const char digits[] = "0123456789abcdef";
  std::string text (16, '0');
  for (int i = 0; i < 16; ++i)
    text[15 - i] = digits[(state_ >> (4 * i)) & 0xf];
  return text;
}

std::string
hashFile (const std::string& path)
{
  std::error_code ec;
  const auto status = std::filesystem::status (path, ec);
  if (!std::filesystem::exists (status))
    throw IoError (path + ": no such file");
  if (!std::filesystem::is_regular_file (status))
    throw IoError (path + ": not a regular file (a folder, a FIFO or a device); cannot take its content hash");
  std::ifstream stream (path, std::ios::binary);
  Fnv1a64 hash;
  std::vector<char> buffer (1 << 20);
  while (stream) {
    stream.read (buffer.data (), static_cast<std::streamsize> (buffer.size ()));
    hash.add (buffer.data (), static_cast<std::size_t> (stream.gcount ()));
  }
  if (!stream.eof ())
    throw IoError (path + ": cannot be read to its end");
  return hash.hex ();
}
} // namespace morphreg
