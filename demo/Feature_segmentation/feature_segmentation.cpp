// SPDX-License-Identifier: GPL-3.0-or-later
// The command-line program of the package: reads a mesh, runs the pipeline stage by
// stage (load -> curvature -> feature lines -> segmentation -> the edits of an edit
// script, if given), each stage and each edit timed, and writes the feature lines
// (CGAL polylines and OBJ), the segmentation (a PLY mesh with a patch id and colour per
// face, and the patch of every vertex and face of the input file) and a JSON summary
// into an output folder. `feature_segmentation edit MESH` serves the interactive editor
// instead (editor_server.h), `feature_segmentation batch INPUTS...` segments many meshes
// (batch_command.h). Bad input or bad options give one "error: ..." line on
// stderr and a non-zero exit status.

#include "batch_command.h"
#include "editor_server.h"
#include "huge_pages.h"
#include "pipeline.h"
#include "program_options.h"
#include "program_usage.h"

#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <new>
#include <optional>
#include <string>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

namespace {

using namespace fs_app;

int run(const Options& options)
{
  const Results results = segment_and_write(options);
  // the patches of the written faces: the smoothed boundaries may leave a patch of the
  // segmentation's line above with no face of its own
  if(!options.quiet)
    std::cerr << "outputs written to " << options.output_dir << "/ (" << results.number_of_patches << " patches)"
              << std::endl;
  return EXIT_SUCCESS;
}

} // namespace

int main(int argc, char** argv)
{
  use_huge_page_heap(argc, argv);
  Options options;
  try
  {
    options = parse_command_line(argc, argv);
  }
  catch(const Usage_error& e)
  {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  }
  if(options.help)
  {
    if(options.help_all) print_usage(std::cout);
    else print_short_usage(std::cout);
    return EXIT_SUCCESS;
  }
#ifdef CGAL_LINKED_WITH_TBB
  // --threads N bounds TBB's threads for the whole run (0: TBB's default, all cores)
  std::optional<tbb::global_control> thread_limit;
  if(options.threads > 0)
    thread_limit.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(options.threads));
#endif
  try
  {
    if(options.command == Command::EDIT)
    {
      create_output_dir(options);
      return run_editor(options);
    }
    if(options.command == Command::BATCH)
      return run_batch(options);
    return run(options);
  }
  catch(const Input_error& e)
  {
    std::cerr << "error: " << e.what() << '\n';
  }
  catch(const Edit_script_error& e)
  {
    std::cerr << "error: " << e.what() << '\n';
  }
  catch(const FS::Invalid_input& e)
  {
    std::cerr << "error: " << options.input << ": " << e.what() << '\n';
  }
  catch(const std::bad_alloc&)
  {
    std::cerr << "error: " << options.input << ": out of memory\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << '\n';
  }
  return EXIT_FAILURE;
}
