// Benchmark of the programs' mesh input (app/Feature_segmentation/mesh_io): fandisk
// subdivided flat (each triangle into 4, same geometry) to 12,946 / 207,136 / 828,544
// faces, written as text OFF, OBJ (`f a//n` faces), binary PLY and binary STL; for each
// file the whole load of the program (parse, checks, repairs, mesh, the fastest of 3),
// the parse alone, CGAL's read_polygon_soup on the same file, and the time to count its
// lines (what `wc -l` does: the floor for reading the bytes). Prints a table and writes
// CSV (--out FILE). The program's heap uses huge pages (huge_pages.h); so does this one.
//
// Usage: bench_mesh_input [--mesh FILE] [--levels 0,2,3] [--out FILE]
#include "bench_common.h"

#include "huge_pages.h"
#include "read_input_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef fs_bench::Soup_point P;
typedef fs_bench::Soup_triangle T;
using fs_bench::subdivide;

namespace {

void write_files(const std::string& stem, const std::vector<P>& points, const std::vector<T>& triangles)
{
  {
    std::FILE* f = std::fopen((stem + ".off").c_str(), "w");
    std::fprintf(f, "OFF\n%zu %zu 0\n", points.size(), triangles.size());
    for(const P& p : points) std::fprintf(f, "%.9g %.9g %.9g\n", p[0], p[1], p[2]);
    for(const T& t : triangles) std::fprintf(f, "3 %u %u %u\n", t[0], t[1], t[2]);
    std::fclose(f);
  }
  {
    std::FILE* f = std::fopen((stem + ".obj").c_str(), "w");
    for(const P& p : points) std::fprintf(f, "v %.9g %.9g %.9g\n", p[0], p[1], p[2]);
    std::fprintf(f, "vn 0 0 1\n");
    for(const T& t : triangles) std::fprintf(f, "f %u//1 %u//1 %u//1\n", t[0] + 1, t[1] + 1, t[2] + 1);
    std::fclose(f);
  }
  {
    std::FILE* f = std::fopen((stem + ".ply").c_str(), "wb");
    std::fprintf(f, "ply\nformat binary_little_endian 1.0\nelement vertex %zu\nproperty float x\n"
                    "property float y\nproperty float z\nelement face %zu\n"
                    "property list uchar int vertex_indices\nend_header\n", points.size(), triangles.size());
    for(const P& p : points) { const float c[3] = {float(p[0]), float(p[1]), float(p[2])}; std::fwrite(c, 4, 3, f); }
    for(const T& t : triangles) { const unsigned char n = 3; std::fwrite(&n, 1, 1, f); std::fwrite(t.data(), 4, 3, f); }
    std::fclose(f);
  }
  {
    std::FILE* f = std::fopen((stem + ".stl").c_str(), "wb");
    char header[80] = "binary STL written by bench_mesh_input";
    std::fwrite(header, 1, 80, f);
    const std::uint32_t n = static_cast<std::uint32_t>(triangles.size());
    std::fwrite(&n, 4, 1, f);
    for(const T& t : triangles)
    {
      float record[12] = {0, 0, 0};
      for(int k = 0; k < 3; ++k)
        for(int d = 0; d < 3; ++d)
          record[3 + 3 * k + d] = float(points[t[k]][d]);
      std::fwrite(record, 4, 12, f);
      const std::uint16_t attribute = 0;
      std::fwrite(&attribute, 2, 1, f);
    }
    std::fclose(f);
  }
}

std::size_t count_lines(const std::string& path)
{
  std::FILE* f = std::fopen(path.c_str(), "rb");
  static std::vector<char> buffer(1 << 20);
  std::size_t lines = 0, got;
  while((got = std::fread(buffer.data(), 1, buffer.size(), f)) > 0)
    for(const char* p = buffer.data(); (p = static_cast<const char*>(std::memchr(p, '\n', buffer.data() + got - p))) != nullptr; ++p)
      ++lines;
  std::fclose(f);
  return lines;
}

} // namespace

int main(int argc, char** argv)
{
  fs_app::use_huge_page_heap(argc, argv);
  std::string mesh_file = std::string(FS_MESH_DIR) + "/fandisk.off", out_csv;
  std::vector<int> levels = {0, 2, 3};
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--mesh" && i + 1 < argc) mesh_file = argv[++i];
    else if(a == "--out" && i + 1 < argc) out_csv = argv[++i];
    else if(a == "--levels" && i + 1 < argc)
    {
      levels.clear();
      std::stringstream ss(argv[++i]);
      for(std::string t; std::getline(ss, t, ',');) levels.push_back(std::stoi(t));
    }
    else { std::cerr << "usage: bench_mesh_input [--mesh FILE] [--levels 0,2,3] [--out FILE]\n"; return 2; }
  }

  fs_app::Mesh_soup soup;
  fs_app::read_mesh_soup(mesh_file, soup);
  std::vector<P> points = soup.points;
  std::vector<T> triangles;
  for(std::size_t f = 0; f < soup.number_of_faces(); ++f)
    triangles.push_back({{soup.face(f)[0], soup.face(f)[1], soup.face(f)[2]}});

  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "fs_bench_mesh_input";
  std::filesystem::create_directories(dir);
  std::cout << "mesh input: " << mesh_file << " subdivided; " << fs_bench::cpu_name()
            << ", one thread; seconds, fastest of 3\n\n";
  std::cout << "| format | faces | MB | load (program) | parse only | CGAL read_polygon_soup | count lines | load / count lines |\n"
            << "|---|---|---|---|---|---|---|---|\n";
  std::ofstream csv;
  if(!out_csv.empty())
  {
    csv.open(out_csv);
    csv << "cpu,format,faces,bytes,load,parse,cgal_read_polygon_soup,count_lines\n";
  }
  int level = 0;
  for(int target : levels)
  {
    while(level < target) { subdivide(points, triangles); ++level; }
    const std::string stem = (dir / ("fandisk_" + std::to_string(triangles.size()))).string();
    write_files(stem, points, triangles);
    for(const char* format : {"off", "obj", "ply", "stl"})
    {
      const std::string path = stem + "." + format;
      const double bytes = double(std::filesystem::file_size(path));
      const double load = fs_bench::fastest(3, [&] { Mesh m; fs_app::read_input_mesh(path, m); });
      const double parse = fs_bench::fastest(3, [&] { fs_app::Mesh_soup s; fs_app::read_mesh_soup(path, s); });
      const double cgal = fs_bench::fastest(3, [&] {
        std::vector<K::Point_3> p; std::vector<std::vector<std::size_t> > f;
        CGAL::IO::read_polygon_soup(path, p, f);
      });
      const double lines = fs_bench::fastest(3, [&] { count_lines(path); });
      std::cout << std::fixed << "| " << format << " | " << triangles.size() << " | " << std::setprecision(1)
                << bytes / 1e6 << " | " << std::setprecision(3) << load << " | " << parse << " | " << cgal
                << " | " << lines << " | " << std::setprecision(1) << load / lines << " |\n";
      if(csv)
        csv << fs_bench::csv_text(fs_bench::cpu_name()) << ',' << format << ',' << triangles.size() << ','
            << bytes << ',' << load << ',' << parse << ',' << cgal << ',' << lines << '\n';
      std::filesystem::remove(path);
    }
  }
  if(csv)
  {
    csv.close();
    fs_bench::write_provenance(out_csv, argc, argv);
  }
  return 0;
}
