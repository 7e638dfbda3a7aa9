// SPDX-License-Identifier: GPL-3.0-or-later
// The parts of the CAD table read with their ground truth: DATA/cad (NAME.obj and
// NAME.labels), DATA/abc-dev (gzipped ABC models with their YAML) and the generated parts.

#ifndef CGAL_FEATURE_SEGMENTATION_BENCHMARK_CAD_PART_READER_H
#define CGAL_FEATURE_SEGMENTATION_BENCHMARK_CAD_PART_READER_H

#include "abc_ground_truth.h"
#include "methods.h"

#include "read_input_mesh.h" // the program's reader: the parts are read as a user's files are

#include <unistd.h> // getpid: a temporary file per process
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace fs_evaluation {

/// A part with its ground truth: the patch (B-rep face, ABC surface) of every face.
struct Cad_part
{
  std::string name;
  Mesh mesh;
  std::vector<int> labels;
};

/// The kinds of ground-truth files: NAME.obj with NAME.labels (DATA/cad), NAME.obj.gz
/// with NAME.labels (DATA/abc-dev: native ABC meshes, gzipped), NAME.obj with NAME.yml
/// (DATA/abc: the ABC feature format); NAME.obj with NAME.labels made by gmsh from the
/// scripts of benchmark/Feature_segmentation/generated (the build's generated parts).
enum class Part_format { OBJ_LABELS, GZIPPED_OBJ_LABELS, ABC_YML, GENERATED_OBJ_LABELS };

/// The set a part belongs to, named as in the tables.
inline std::string part_set(Part_format format)
{
  switch(format)
  {
    case Part_format::OBJ_LABELS: return "cad";
    case Part_format::GZIPPED_OBJ_LABELS: return "abc-dev";
    case Part_format::GENERATED_OBJ_LABELS: return "generated";
    default: return "abc";
  }
}

/// Unpacks the gzip file `gz` into the file `out`. Returns false with `error` set on failure.
inline bool gunzip_file(const std::filesystem::path& gz, const std::filesystem::path& out, std::string& error)
{
  gzFile in = gzopen(gz.string().c_str(), "rb");
  if(in == nullptr)
  {
    error = "cannot open " + gz.string();
    return false;
  }
  std::ofstream file(out, std::ios::binary);
  std::vector<char> buffer(1 << 16);
  int n = 0;
  while((n = gzread(in, buffer.data(), static_cast<unsigned>(buffer.size()))) > 0)
    file.write(buffer.data(), n);
  int code = Z_OK;
  const char* message = gzerror(in, &code);
  gzclose(in);
  if(n < 0 || code != Z_OK || !file)
  {
    error = "cannot unpack " + gz.string() + (n < 0 ? std::string(": ") + message : std::string());
    return false;
  }
  return true;
}

/// The file's labels, one per face of the file, put on the mesh faces the program's
/// reader made of them (a duplicate face of the file keeps its first occurrence's face).
inline bool read_labels_of_file_faces(const std::filesystem::path& path,
                                      const fs_app::Input_correspondence<Mesh>& correspondence,
                                      std::size_t number_of_faces, std::vector<int>& labels, std::string& error)
{
  std::ifstream in(path);
  std::vector<int> file_labels;
  int label;
  while(in >> label) file_labels.push_back(label);
  if(file_labels.size() != correspondence.face_of_file_face.size())
  {
    error = path.string() + ": " + std::to_string(file_labels.size()) + " labels for " +
            std::to_string(correspondence.face_of_file_face.size()) + " faces";
    return false;
  }
  labels.assign(number_of_faces, -1);
  std::vector<face_descriptor> mesh_faces;
  for(std::size_t f = file_labels.size(); f-- > 0;) // the first occurrence wins
  {
    mesh_faces.clear();
    correspondence.mesh_faces_of_file_face(f, mesh_faces);
    for(face_descriptor m : mesh_faces) labels[m.idx()] = file_labels[f];
  }
  return true;
}

/// Reads a part (Part_format): a NAME.obj or NAME.obj.gz (unpacked into a temporary file)
/// with the program's reader, which repairs as it does for a user (duplicates, edges of
/// more than two faces), and NAME.labels; or NAME.obj with NAME.yml (the name gets "abc_"
/// before it). Returns false with `error` set when the mesh or its labels cannot be read,
/// or when a face has no label.
inline bool read_cad_part(const std::filesystem::path& path, Part_format format, Cad_part& part, std::string& error)
{
  namespace fsys = std::filesystem;
  if(format == Part_format::ABC_YML)
  {
    if(!read_mesh_in_file_order(path.string(), part.mesh, error)) return false;
    part.name = "abc_" + path.stem().string();
    try
    {
      part.labels = read_abc_ground_truth(fsys::path(path).replace_extension(".yml").string(),
                                          part.mesh.number_of_vertices(), part.mesh.number_of_faces())
                      .face_patch;
    }
    catch(const std::exception& e)
    {
      error = e.what();
      return false;
    }
  }
  else
  {
    fsys::path obj = path, stem = fsys::path(path).replace_extension(); // NAME.obj.gz -> NAME.obj
    if(format == Part_format::GZIPPED_OBJ_LABELS)
    {
      std::error_code ec;
      obj = fsys::temp_directory_path(ec) / ("fs_evaluation_" + std::to_string(::getpid()) + "_" +
                                             stem.filename().string());
      if(!gunzip_file(path, obj, error)) return false;
    }
    stem.replace_extension();
    part.name = stem.filename().string();
    fs_app::Input_correspondence<Mesh> correspondence;
    bool ok = true;
    try
    {
      const fs_app::Read_report report = fs_app::read_input_mesh(obj.string(), part.mesh, correspondence);
      for(const std::string& notice : report.notices)
        std::cerr << "evaluate_quality: " << part.name << ": " << notice << std::endl;
    }
    catch(const std::exception& e)
    {
      error = e.what();
      ok = false;
    }
    if(format == Part_format::GZIPPED_OBJ_LABELS)
    {
      std::error_code ec;
      fsys::remove(obj, ec);
    }
    if(!ok) return false;
    if(!read_labels_of_file_faces(fsys::path(stem).replace_extension(".labels"), correspondence,
                                  part.mesh.number_of_faces(), part.labels, error))
      return false;
  }
  const std::size_t faces = part.mesh.number_of_faces();
  if(part.labels.size() != faces || *std::min_element(part.labels.begin(), part.labels.end()) < 0)
  {
    error = "not one label >= 0 per face (" + std::to_string(part.labels.size()) + " labels, " +
            std::to_string(faces) + " faces)";
    return false;
  }
  return true;
}

} // namespace fs_evaluation

#endif // CGAL_FEATURE_SEGMENTATION_BENCHMARK_CAD_PART_READER_H
