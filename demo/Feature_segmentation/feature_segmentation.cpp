// SPDX-License-Identifier: GPL-3.0-or-later
// The command-line program of the package: reads a mesh, runs the pipeline stage by
// stage (load -> curvature -> feature lines -> segmentation -> the edits of an edit
// script, if given), each stage and each edit timed, and writes the feature lines
// (CGAL polylines and OBJ), the segmentation (a PLY mesh with a patch id and colour per
// face, and the patch of every vertex and face of the input file) and a JSON summary
// into an output folder. `feature_segmentation edit MESH` serves the interactive editor
// instead (editor_server.h). Bad input or bad options give one "error: ..." line on
// stderr and a non-zero exit status.

#include "editor_server.h"
#include "huge_pages.h"
#include "pipeline.h"
#include "program_options.h"

#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <new>
#include <string>

namespace {

using namespace fs_demo;

// Creates the output folder, or fails with a clear message before any time is spent on
// the mesh.
void create_output_dir(const Options& options)
{
  std::error_code ec;
  std::filesystem::create_directories(options.output_dir, ec);
  if(ec || !std::filesystem::is_directory(options.output_dir))
    throw std::runtime_error(options.output_dir + ": cannot create the output folder" +
                             (ec ? " (" + ec.message() + ")" : std::string()));
}

int run(const Options& options)
{
  Stage_timer timer(options.quiet);
  Results results;
  create_output_dir(options);

  // A mistake in the edit script is found before the mesh is read; face indices are
  // checked against the file as soon as it is read.
  Edit_script script;
  if(!options.edits_file.empty())
    script = read_edit_script(options.edits_file);

  Pipeline pipeline(options, timer, results);
  pipeline.load();
  check_face_indices(script, results.read_report.number_of_file_faces, num_faces(pipeline.mesh));
  pipeline.segment();

  if(!script.edits.empty())
  {
    Edit_runner<Mesh, K>& runner = pipeline.edit_runner();
    timer.run("edits", [&]() {
      for(const Script_edit& e : script.edits)
      {
        results.edits.push_back(runner.apply(script, e));
        const Edit_record& r = results.edits.back();
        if(!options.quiet)
          std::cerr << "edit " << options.edits_file << ":" << r.line << ": " << r.verb << ": "
                    << r.patches << " patches, cut cost " << r.cut_cost << " (" << std::fixed
                    << std::setprecision(3) << r.seconds << " s)" << std::defaultfloat << std::endl;
      }
    });
  }
  pipeline.write_outputs();
  if(!options.quiet)
    std::cerr << "outputs written to " << options.output_dir << "/" << std::endl;
  return EXIT_SUCCESS;
}

} // namespace

int main(int argc, char** argv)
{
  use_huge_page_heap(argv);
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
    print_usage(std::cout);
    return EXIT_SUCCESS;
  }
  try
  {
    if(options.command == Command::EDIT)
    {
      create_output_dir(options);
      return run_editor(options);
    }
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
