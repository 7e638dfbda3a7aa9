// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target for one mesh reader of the programs, FS_FUZZ_FORMAT ("off", "obj",
// "ply" or "stl"), and the repairs after it (fuzz_mesh_reader_core.cpp).
#include <cstddef>
#include <cstdint>

int fs_fuzz_mesh_reader(const char* format, const std::uint8_t* data, std::size_t size);

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  return fs_fuzz_mesh_reader(FS_FUZZ_FORMAT, data, size);
}
