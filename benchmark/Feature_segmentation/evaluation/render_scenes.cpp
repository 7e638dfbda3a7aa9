// SPDX-License-Identifier: GPL-3.0-or-later
//
// Draws the tiles of the evaluation's contact sheets: for every tile of a scene written
// by evaluate_quality (the mesh, a colour per face, segments over the surface), a PNG
// with two views of the shaded mesh (front and back, so no side stays hidden), patch
// boundaries in black where the face colours change (unless the tile says
// "face_boundaries 0": its segments are the boundaries, e.g. smoothed curves), and the
// segments (feature lines, curves). A "blank" entry is an empty place in the sheet. Rendering is
// Mesa's off-screen OpenGL (OSMesa, Debian package libosmesa6-dev: a software OpenGL
// implementation, no display or GPU needed), images are written with libpng; each view
// is drawn at twice the size and averaged down for smooth edges.
//
// Usage: render_scenes SCENE OUTPUT_PREFIX [TILE_SIZE]
// Writes OUTPUT_PREFIX_NN.png per tile and prints "PATH<TAB>LABEL" lines on stdout,
// "null:<TAB>" for a blank (ImageMagick's empty image).

#include <GL/osmesa.h>
#include <GL/gl.h>
#include <png.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

struct Segment
{
  float a[3], b[3];
  unsigned char rgb[3];
  float width;
};

struct Tile
{
  bool blank = false;
  bool face_boundaries = true;
  std::string label;
  std::vector<std::array<unsigned char, 3> > colour; // per face
  std::vector<Segment> segments;
};

struct Scene
{
  std::vector<std::array<float, 3> > points;
  std::vector<std::array<unsigned, 3> > faces;
  std::vector<Tile> tiles;
};

[[noreturn]] void fail(const std::string& what)
{
  std::cerr << "render_scenes: " << what << std::endl;
  std::exit(1);
}

std::array<unsigned char, 3> hex_colour(const std::string& s)
{
  if(s.size() != 6) fail("bad colour '" + s + "'");
  const unsigned long v = std::strtoul(s.c_str(), nullptr, 16);
  return {static_cast<unsigned char>(v >> 16), static_cast<unsigned char>((v >> 8) & 255),
          static_cast<unsigned char>(v & 255)};
}

Scene read_scene(const std::string& path)
{
  std::ifstream in(path);
  if(!in) fail("cannot read " + path);
  Scene sc;
  std::string word;
  std::size_t n = 0;
  in >> word >> n;
  if(word != "fs_scene" || n != 1) fail(path + ": not an fs_scene file");
  in >> word >> n;
  if(word != "vertices") fail(path + ": expected 'vertices'");
  sc.points.resize(n);
  for(auto& p : sc.points) in >> p[0] >> p[1] >> p[2];
  in >> word >> n;
  if(word != "faces") fail(path + ": expected 'faces'");
  sc.faces.resize(n);
  for(auto& f : sc.faces)
  {
    in >> f[0] >> f[1] >> f[2];
    for(unsigned v : f)
      if(v >= sc.points.size()) fail(path + ": face index out of range");
  }
  while(in >> word)
  {
    Tile t;
    if(word == "blank")
    {
      t.blank = true;
      sc.tiles.push_back(std::move(t));
      continue;
    }
    if(word != "tile") fail(path + ": expected 'tile' or 'blank', got '" + word + "'");
    std::getline(in, t.label);
    t.label.erase(0, t.label.find_first_not_of(' '));
    std::string line;
    std::getline(in, line);
    std::istringstream ls(line);
    ls >> word;
    if(word != "colours") fail(path + ": expected 'colours'");
    std::string uniform;
    if(ls >> uniform)
    {
      if(uniform != "uniform" || !(ls >> word)) fail(path + ": bad 'colours' line");
      t.colour.assign(sc.faces.size(), hex_colour(word));
    }
    else
    {
      t.colour.resize(sc.faces.size());
      for(auto& c : t.colour)
      {
        in >> word;
        c = hex_colour(word);
      }
    }
    in >> word >> n;
    if(word == "face_boundaries")
    {
      t.face_boundaries = n != 0;
      in >> word >> n;
    }
    if(word != "segments") fail(path + ": expected 'segments'");
    t.segments.resize(n);
    for(auto& s : t.segments)
    {
      in >> s.a[0] >> s.a[1] >> s.a[2] >> s.b[0] >> s.b[1] >> s.b[2] >> word >> s.width;
      const auto c = hex_colour(word);
      std::copy(c.begin(), c.end(), s.rgb);
    }
    if(!in) fail(path + ": truncated tile '" + t.label + "'");
    sc.tiles.push_back(std::move(t));
  }
  return sc;
}

void write_png(const std::string& path, int w, int h, const std::vector<unsigned char>& rgb)
{
  FILE* fp = std::fopen(path.c_str(), "wb");
  if(!fp) fail("cannot write " + path);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if(!png || !info || setjmp(png_jmpbuf(png))) fail("libpng failed on " + path);
  png_init_io(png, fp);
  png_set_IHDR(png, info, w, h, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for(int y = 0; y < h; ++y) png_write_row(png, const_cast<png_bytep>(&rgb[static_cast<std::size_t>(y) * w * 3]));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  std::fclose(fp);
}

// The patch boundaries: edges whose two faces have different colours.
std::vector<std::pair<unsigned, unsigned> > boundary_edges(const Scene& sc, const Tile& t)
{
  std::map<std::pair<unsigned, unsigned>, std::size_t> first_face;
  std::vector<std::pair<unsigned, unsigned> > result;
  for(std::size_t f = 0; f < sc.faces.size(); ++f)
    for(int i = 0; i < 3; ++i)
    {
      unsigned a = sc.faces[f][i], b = sc.faces[f][(i + 1) % 3];
      if(a > b) std::swap(a, b);
      auto it = first_face.emplace(std::make_pair(a, b), f);
      if(!it.second && t.colour[it.first->second] != t.colour[f]) result.emplace_back(a, b);
    }
  return result;
}

class Renderer
{
public:
  Renderer(int size, const Scene& sc) : m_size(size), m_buffer(static_cast<std::size_t>(size) * size * 4)
  {
    m_ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    if(!m_ctx || !OSMesaMakeCurrent(m_ctx, m_buffer.data(), GL_UNSIGNED_BYTE, size, size))
      fail("cannot create an OSMesa context");
    // The camera frames the bounding sphere of the mesh.
    float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
    for(const auto& p : sc.points)
      for(int i = 0; i < 3; ++i) { lo[i] = std::min(lo[i], p[i]); hi[i] = std::max(hi[i], p[i]); }
    for(int i = 0; i < 3; ++i) m_centre[i] = (lo[i] + hi[i]) / 2;
    m_radius = 0.5f * std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                                (hi[2] - lo[2]) * (hi[2] - lo[2]));
    if(!(m_radius > 0)) m_radius = 1;
    // Flat shading with the face normals: CAD creases stay crisp.
    m_face_normals.resize(sc.faces.size());
    for(std::size_t f = 0; f < sc.faces.size(); ++f)
    {
      const auto& a = sc.points[sc.faces[f][0]];
      const auto& b = sc.points[sc.faces[f][1]];
      const auto& c = sc.points[sc.faces[f][2]];
      const float u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
      std::array<float, 3> n = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
      const float l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      if(l > 0) for(float& x : n) x /= l;
      m_face_normals[f] = n;
    }
  }
  ~Renderer() { OSMesaDestroyContext(m_ctx); }

  // One view (`side` 0: front, 1: back) into an RGB image of m_size x m_size.
  std::vector<unsigned char> draw(const Scene& sc, const Tile& t,
                                  const std::vector<std::pair<unsigned, unsigned> >& boundary, int side)
  {
    glViewport(0, 0, m_size, m_size);
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    const float r = m_radius * 1.05f;
    glOrtho(-r, r, -r, r, -4 * r, 4 * r);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    // Lights fixed to the camera.
    const GLfloat key[] = {0.4f, 0.6f, 1.f, 0.f}, fill[] = {-0.6f, -0.2f, 0.6f, 0.f};
    const GLfloat white[] = {0.75f, 0.75f, 0.75f, 1.f}, dim[] = {0.3f, 0.3f, 0.3f, 1.f}, amb[] = {0.3f, 0.3f, 0.3f, 1.f};
    glLightfv(GL_LIGHT0, GL_POSITION, key);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT1, GL_POSITION, fill);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, dim);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    // An oblique view from above, turned by 180 degrees for the back view.
    glRotatef(25.f, 1.f, 0.f, 0.f);
    glRotatef(side == 0 ? -35.f : 145.f, 0.f, 1.f, 0.f);
    glTranslatef(-m_centre[0], -m_centre[1], -m_centre[2]);

    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glEnable(GL_NORMALIZE);
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.f, 2.f); // lines drawn on the surface stay in front of it
    glBegin(GL_TRIANGLES);
    for(std::size_t f = 0; f < sc.faces.size(); ++f)
    {
      glColor3ub(t.colour[f][0], t.colour[f][1], t.colour[f][2]);
      glNormal3fv(m_face_normals[f].data());
      for(unsigned v : sc.faces[f]) glVertex3fv(sc.points[v].data());
    }
    glEnd();
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_LIGHTING);

    glEnable(GL_LINE_SMOOTH);
    glLineWidth(2.f * m_size / 800.f + 1.f);
    glColor3ub(20, 20, 20);
    glBegin(GL_LINES);
    for(const auto& e : boundary)
    {
      glVertex3fv(sc.points[e.first].data());
      glVertex3fv(sc.points[e.second].data());
    }
    glEnd();
    std::vector<float> widths;
    for(const auto& s : t.segments) widths.push_back(s.width);
    std::sort(widths.begin(), widths.end());
    widths.erase(std::unique(widths.begin(), widths.end()), widths.end());
    for(float w : widths)
    {
      glLineWidth(w * m_size / 400.f);
      glBegin(GL_LINES);
      for(const auto& s : t.segments)
        if(s.width == w)
        {
          glColor3ubv(s.rgb);
          glVertex3fv(s.a);
          glVertex3fv(s.b);
        }
      glEnd();
    }
    glFinish();
    std::vector<unsigned char> rgb(static_cast<std::size_t>(m_size) * m_size * 3);
    for(int y = 0; y < m_size; ++y) // OpenGL rows go bottom-up
      for(int x = 0; x < m_size; ++x)
        for(int c = 0; c < 3; ++c)
          rgb[(static_cast<std::size_t>(y) * m_size + x) * 3 + c] =
            m_buffer[(static_cast<std::size_t>(m_size - 1 - y) * m_size + x) * 4 + c];
    return rgb;
  }

private:
  int m_size;
  std::vector<unsigned char> m_buffer;
  OSMesaContext m_ctx = nullptr;
  float m_centre[3] = {0, 0, 0};
  float m_radius = 1;
  std::vector<std::array<float, 3> > m_face_normals;
};

} // namespace

int main(int argc, char** argv)
{
  if(argc < 3 || argc > 4)
  {
    std::cerr << "usage: render_scenes SCENE OUTPUT_PREFIX [TILE_SIZE]" << std::endl;
    return 2;
  }
  const int size = argc == 4 ? std::atoi(argv[3]) : 360; // height of a tile; its width is twice
  if(size < 16 || size > 4096) fail("bad tile size");
  const Scene sc = read_scene(argv[1]);
  Renderer renderer(2 * size, sc); // drawn at twice the size, then averaged 2x2
  for(std::size_t i = 0; i < sc.tiles.size(); ++i)
  {
    const Tile& t = sc.tiles[i];
    if(t.blank)
    {
      std::cout << "null:\t\n";
      continue;
    }
    const auto boundary = t.face_boundaries ? boundary_edges(sc, t) : std::vector<std::pair<unsigned, unsigned> >();
    std::vector<unsigned char> out(static_cast<std::size_t>(2 * size) * size * 3);
    for(int side = 0; side < 2; ++side)
    {
      const std::vector<unsigned char> big = renderer.draw(sc, t, boundary, side);
      for(int y = 0; y < size; ++y)
        for(int x = 0; x < size; ++x)
          for(int c = 0; c < 3; ++c)
          {
            int sum = 0;
            for(int dy = 0; dy < 2; ++dy)
              for(int dx = 0; dx < 2; ++dx)
                sum += big[(static_cast<std::size_t>(2 * y + dy) * 2 * size + 2 * x + dx) * 3 + c];
            out[(static_cast<std::size_t>(y) * 2 * size + side * size + x) * 3 + c] = static_cast<unsigned char>(sum / 4);
          }
    }
    char suffix[32];
    std::snprintf(suffix, sizeof(suffix), "_%02zu.png", i);
    const std::string path = std::string(argv[2]) + suffix;
    write_png(path, 2 * size, size, out);
    std::cout << path << "\t" << t.label << "\n";
  }
  return 0;
}
