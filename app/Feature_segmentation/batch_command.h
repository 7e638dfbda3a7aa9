// SPDX-License-Identifier: GPL-3.0-or-later
// `feature_segmentation batch INPUTS... --output-dir DIR [--jobs N] [--force]`: the
// pipeline of `segment` over many meshes, N at a time (threads; each mesh has its own
// Pipeline), one output folder per mesh, one table for all (batch_summary.csv and
// batch_summary.jsonl, a row per mesh in input order, whatever order they finish in).
// Resumable: a mesh whose folder holds a summary.json of the same input (written last by
// a complete run) is skipped unless --force. A mesh that fails is recorded with its error
// and the others go on.

#ifndef CGAL_FEATURE_SEGMENTATION_APP_BATCH_COMMAND_H
#define CGAL_FEATURE_SEGMENTATION_APP_BATCH_COMMAND_H

#include "pipeline.h"
#include "option_table.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace fs_app {

/// One mesh of a batch: its row of the summary table.
struct Batch_row
{
  std::string mesh;      ///< the input file, as given (or as found in a folder or list)
  std::string output;    ///< its output folder
  std::size_t faces = 0, patches = 0;
  double cut_cost = 0, seconds = 0;
  std::string status;    ///< "done", "skipped" (complete outputs found) or "failed"
  std::string error;     ///< why it failed
};

namespace internal {

inline bool is_mesh_file(const std::filesystem::path& p)
{
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".off" || ext == ".obj" || ext == ".ply" || ext == ".stl";
}

// The meshes of INPUTS, in order: a folder gives its mesh files (recursively, sorted), a
// .txt file the paths it lists (relative ones from its folder), anything else itself (a
// missing file becomes a failed row, not an error of the batch).
inline std::vector<std::string> batch_meshes(const std::vector<std::string>& inputs)
{
  namespace sfs = std::filesystem;
  std::vector<std::string> meshes;
  for(const std::string& input : inputs)
  {
    std::error_code ec;
    if(sfs::is_directory(input, ec))
    {
      std::vector<std::string> found;
      for(sfs::recursive_directory_iterator it(input, sfs::directory_options::skip_permission_denied, ec), end;
          !ec && it != end; it.increment(ec))
        if(it->is_regular_file(ec) && is_mesh_file(it->path())) found.push_back(it->path().string());
      if(ec) throw std::runtime_error(input + ": cannot list the folder (" + ec.message() + ")");
      std::sort(found.begin(), found.end());
      meshes.insert(meshes.end(), found.begin(), found.end());
    }
    else if(sfs::path(input).extension() == ".txt" && sfs::is_regular_file(input, ec))
    {
      std::ifstream list(input);
      if(!list) throw std::runtime_error(input + ": cannot read the list");
      const sfs::path base = sfs::path(input).parent_path();
      for(std::string line; std::getline(list, line);)
      {
        const std::size_t hash = line.find('#');
        if(hash != std::string::npos) line.erase(hash);
        line.erase(0, line.find_first_not_of(" \t\r"));
        line.erase(line.find_last_not_of(" \t\r") + 1);
        if(line.empty()) continue;
        const sfs::path p(line);
        meshes.push_back((p.is_absolute() || base.empty() ? p : base / p).string());
      }
    }
    else
      meshes.push_back(input);
  }
  return meshes;
}

// The output folder of each mesh: its file name without extension, "_2", "_3", ...
// appended where two meshes would share one (in input order, so a rerun agrees).
inline std::vector<std::string> batch_folders(const std::vector<std::string>& meshes)
{
  std::set<std::string> used;
  std::vector<std::string> names;
  for(const std::string& m : meshes)
  {
    std::string stem = std::filesystem::path(m).stem().string();
    if(stem.empty() || stem == "." || stem == "..") stem = "mesh";
    std::string name = stem;
    for(int k = 2; used.count(name); ++k) name = stem + "_" + std::to_string(k);
    used.insert(name);
    names.push_back(name);
  }
  return names;
}

inline std::string csv_field(const std::string& s)
{
  if(s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for(char c : s) { if(c == '"') q += '"'; q += c; }
  return q + "\"";
}

// The row of a mesh whose complete outputs (summary.json of the same input) exist.
inline bool read_finished_row(const std::filesystem::path& summary, Batch_row& row)
{
  std::ifstream in(summary);
  if(!in) return false;
  try
  {
    const nlohmann::json j = nlohmann::json::parse(in);
    if(j.at("input").get<std::string>() != row.mesh) return false;
    row.faces = j.at("mesh").at("faces").get<std::size_t>();
    row.patches = j.at("segmentation").at("patches").get<std::size_t>();
    row.cut_cost = j.at("segmentation").at("cut_cost").get<double>();
    row.seconds = j.at("seconds").at("total").get<double>();
    return true;
  }
  catch(const nlohmann::json::exception&)
  {
    return false; // not ours, or damaged: done again
  }
}

} // namespace internal

/// Writes the table of a batch as CSV and as JSON lines.
inline void write_batch_summary(const std::filesystem::path& dir, const std::vector<Batch_row>& rows)
{
  write_file(dir / "batch_summary.csv", [&](std::ostream& os) {
    os << "mesh,output,faces,patches,cut_cost,seconds,status,error\n";
    for(const Batch_row& r : rows)
      os << internal::csv_field(r.mesh) << ',' << internal::csv_field(r.output) << ',' << r.faces << ','
         << r.patches << ',' << number_text(r.cut_cost) << ',' << number_text(r.seconds) << ',' << r.status << ','
         << internal::csv_field(r.error) << '\n';
  });
  write_file(dir / "batch_summary.jsonl", [&](std::ostream& os) {
    for(const Batch_row& r : rows)
      os << nlohmann::ordered_json{{"mesh", r.mesh},       {"output", r.output},   {"faces", r.faces},
                                   {"patches", r.patches}, {"cut_cost", r.cut_cost}, {"seconds", r.seconds},
                                   {"status", r.status},   {"error", r.error}}
              .dump()
         << '\n';
  });
}

/// Runs a batch; returns the exit status (1 if any mesh failed).
inline int run_batch(const Options& options)
{
  namespace sfs = std::filesystem;
  typedef std::chrono::steady_clock Clock;
  const sfs::path dir(options.output_dir);
  create_output_dir(options);
  const std::vector<std::string> meshes = internal::batch_meshes(options.inputs);
  if(meshes.empty())
    throw std::runtime_error("batch: no mesh found in the inputs");
  const std::vector<std::string> folders = internal::batch_folders(meshes);
  std::vector<Batch_row> rows(meshes.size());
  for(std::size_t i = 0; i < meshes.size(); ++i)
  {
    rows[i].mesh = meshes[i];
    rows[i].output = (dir / folders[i]).string();
  }

  std::atomic<std::size_t> next(0);
  std::size_t finished = 0, ran = 0;
  std::mutex report;
  const auto start = Clock::now();
  auto work = [&]() {
    for(std::size_t i; (i = next++) < rows.size();)
    {
      Batch_row& row = rows[i];
      const auto t0 = Clock::now();
      if(!options.force && internal::read_finished_row(sfs::path(row.output) / "summary.json", row))
        row.status = "skipped";
      else
      {
        Options one = options;
        one.command = Command::SEGMENT;
        one.input = row.mesh;
        one.output_dir = row.output;
        one.quiet = true;
        try
        {
          const Results r = segment_and_write(one);
          row.faces = r.number_of_faces;
          row.patches = r.number_of_patches;
          row.cut_cost = r.cut_cost;
          row.status = "done";
        }
        catch(const std::bad_alloc&) { row.status = "failed"; row.error = "out of memory"; }
        catch(const std::exception& e) { row.status = "failed"; row.error = e.what(); }
        row.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
      }
      std::lock_guard<std::mutex> lock(report);
      ++finished;
      if(row.status != "skipped") ++ran;
      if(!options.quiet)
      {
        const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
        std::cerr << "progress: [" << finished << "/" << rows.size() << "] " << row.mesh << ": ";
        if(row.status == "failed") std::cerr << "failed: " << row.error;
        else std::cerr << row.patches << " patches" << (row.status == "skipped" ? " (done before, skipped)" : "");
        if(ran > 0 && finished < rows.size())
          std::cerr << "; about " << std::fixed << std::setprecision(0)
                    << elapsed / double(finished) * double(rows.size() - finished) << " s left" << std::defaultfloat;
        std::cerr << std::endl;
      }
    }
  };
  const std::size_t jobs = std::min<std::size_t>(std::size_t(options.jobs), rows.size());
  std::vector<std::thread> threads;
  for(std::size_t t = 1; t < jobs; ++t) threads.emplace_back(work);
  work();
  for(std::thread& t : threads) t.join();

  write_batch_summary(dir, rows);
  const std::size_t failed = std::count_if(rows.begin(), rows.end(), [](const Batch_row& r) { return r.status == "failed"; });
  if(!options.quiet)
    std::cerr << "batch: " << rows.size() << " meshes, " << ran - failed << " segmented, "
              << rows.size() - ran << " skipped, " << failed << " failed; table in "
              << (dir / "batch_summary.csv").string() << std::endl;
  return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_BATCH_COMMAND_H
