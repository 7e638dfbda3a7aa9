// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target for the edit-script parser of the program: any text must give a
// script or one `Edit_script_error`.
#include "edit_script.h"

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try
  {
    const fs_demo::Edit_script script = fs_demo::read_edit_script(in, "input.edits");
    fs_demo::check_face_indices(script, 12);
  }
  catch(const fs_demo::Edit_script_error&)
  {
  }
  return 0;
}
