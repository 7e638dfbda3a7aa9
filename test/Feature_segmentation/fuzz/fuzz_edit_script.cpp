// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target for the edit-script parser of the program: any text must give a
// script or one `Edit_script_error`; a script, written back (as the editor saves its
// sessions), must read back to the same text.
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
    const fs_app::Edit_script script = fs_app::read_edit_script(in, "input.edits");
    std::ostringstream once, twice;
    fs_app::write_edit_script(once, script.edits);
    std::istringstream again(once.str());
    try
    {
      fs_app::write_edit_script(twice, fs_app::read_edit_script(again, "written.edits").edits);
    }
    catch(const fs_app::Edit_script_error&)
    {
      __builtin_trap(); // the reader refuses what the writer wrote
    }
    if(once.str() != twice.str())
      __builtin_trap(); // the writer and the reader disagree
    fs_app::check_face_indices(script, 12, 12);
  }
  catch(const fs_app::Edit_script_error&)
  {
  }
  return 0;
}
