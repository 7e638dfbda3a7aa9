// SPDX-License-Identifier: GPL-3.0-or-later
// The --help and --help-all texts of the program `feature_segmentation`.

#ifndef CGAL_FEATURE_SEGMENTATION_APP_PROGRAM_USAGE_H
#define CGAL_FEATURE_SEGMENTATION_APP_PROGRAM_USAGE_H

#include "program_options.h"

#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace fs_app {

// The three forms of the command line, then a blank line.
inline void print_usage_lines(std::ostream& os)
{
  os << "Usage: " << program_name << " [segment] [MESH] [--output-dir DIR] [options]\n"
     << "       " << program_name << " edit [MESH] [--port N] [--host H] [--output-dir DIR] [options]\n"
     << "       " << program_name << " batch INPUTS... --output-dir DIR [--jobs N] [--force] [options]\n"
     << "\n";
}

// --help: the usage and the options of option_table.h, one line each, to fit a screen.
inline void print_short_usage(std::ostream& os)
{
  print_usage_lines(os);
  os << "Segments a triangle mesh (.off, .obj, .ply, .stl; default: fandisk) into patches\n"
     << "bounded by its creases, ridges and valleys, and writes into DIR: segmentation.ply\n"
     << "(a patch_id and colour per face), face_patches.txt and vertex_patches.txt (in the\n"
     << "file's order), feature_lines.* and boundaries.* (typed polylines), summary.json.\n"
     << "edit serves the interactive editor on http://127.0.0.1:8080/; batch runs many meshes.\n"
     << "\n"
     << "Options:\n";
  const Options defaults;
  for(const Option_entry& e : option_table())
  {
    std::string left = "  " + e.flag() + (e.metavar.empty() ? "" : " " + e.metavar);
    // the words of the help; the default is one word, kept on one line
    std::vector<std::string> words;
    std::istringstream help((e.only ? std::string(*e.only == Command::EDIT ? "edit: " : "batch: ") : "") + e.help);
    for(std::string w; help >> w;) words.push_back(w);
    const std::string shown = e.effective_value(defaults);
    if(e.kind != Option_kind::SWITCH && !shown.empty())
      words.push_back("(default: " + shown + ")");
    // at column 28, on the next line after a long flag, in lines of 80 columns
    if(left.size() >= 28) left += "\n" + std::string(28, ' ');
    else left.resize(28, ' ');
    os << left;
    std::size_t column = 28;
    for(const std::string& w : words)
    {
      if(column > 28 && column + 1 + w.size() > 80)
      {
        os << "\n" << std::string(28, ' ');
        column = 28;
      }
      else if(column > 28)
      {
        os << ' ';
        ++column;
      }
      os << w;
      column += w.size();
    }
    os << "\n";
  }
}

// --help-all: everything.
inline void print_usage(std::ostream& os)
{
  print_usage_lines(os);
  os << "batch: segments every mesh of INPUTS (mesh files; folders, searched recursively\n"
     << "for .off, .obj, .ply and .stl files; list files, .txt, one path per line, '#'\n"
     << "comments) into DIR/NAME/ (NAME: the file's name without extension, made unique),\n"
     << "N meshes at a time (default 1), and writes DIR/batch_summary.csv and\n"
     << "DIR/batch_summary.jsonl (mesh, output, faces, patches, cut cost, seconds, status,\n"
     << "error: a row per mesh, in input order). A mesh whose folder holds a summary.json\n"
     << "is skipped unless --force; a mesh that fails is recorded and the batch goes on;\n"
     << "the exit status is 1 if any failed.\n"
     << "\n"
     << "edit: segments MESH, then serves the interactive editor, a web page, at\n"
     << "http://H:N/ (default http://127.0.0.1:8080/; only this machine can reach it\n"
     << "unless --host names another address); its Save button writes the outputs below\n"
     << "and DIR/edits.txt, the edit script that replays the session with --edits.\n"
     << "Stop it with Ctrl+C.\n"
     << "\n"
     << "Detects the features of a triangle mesh (creases and seams of CAD tessellations,\n"
     << "ridges and valleys, the user's lines) and writes\n"
     << "  DIR/feature_lines.polylines.txt  CGAL polylines, one feature line per line of text\n"
     << "  DIR/feature_lines.types.txt      the type of each: crease, seam, seam_line, ridge,\n"
     << "                                   valley, user\n"
     << "  DIR/feature_lines.obj            the same lines as OBJ line elements, an object a type\n"
     << "and segments it into patches bounded by them (correlation clustering), writing\n"
     << "  DIR/segmentation.ply             the mesh (triangulated, repaired) with a patch_id\n"
     << "                                   and a red, green, blue colour per face\n"
     << "  DIR/face_patches.txt             the patch of every face of MESH, one per line\n"
     << "  DIR/vertex_patches.txt           the patch of every vertex of MESH, one per line\n"
     << "  DIR/boundaries.polylines.txt     every boundary between two patches: CGAL\n"
     << "                                   polylines, one curve per line of text, along\n"
     << "                                   creases or smoothed inside faces\n"
     << "  DIR/boundaries.types.txt         the kind of each: crease or smoothed\n"
     << "  DIR/segmentation_refined.ply     the mesh refined along the smoothed boundaries,\n"
     << "                                   every face in one patch (patch_id and colour)\n"
     << "  DIR/summary.json                 mesh and feature counts, patches, cut cost,\n"
     << "                                   oversegments, seconds per stage, and for each\n"
     << "                                   edit of --edits its patches, cut cost, seconds;\n"
     << "                                   boundary curves and lengths before and after\n"
     << "                                   the smoothing\n"
     << "\n"
     << "MESH is an .off, .obj, .ply or .stl file (default: " << FS_MESH_DIR << "/fandisk.off).\n"
     << "Quads and polygons are triangulated, duplicate points and faces removed, with a\n"
     << "notice on stderr.\n"
     << "\n"
     << "Patch files follow the input file's order: line i is the patch of its i-th vertex\n"
     << "(or face). Patches are numbered from 0. A face has the patch covering most of its\n"
     << "area under the smoothed boundaries (below), and along a crease its own side's; a\n"
     << "quad or polygon that was triangulated has the patch of its first triangle. A\n"
     << "vertex has its patch after the smoothing. A duplicate vertex\n"
     << "(same position as an earlier one) or duplicate face (same vertices as an earlier\n"
     << "one) has the patch of that earlier one; a pinched (non-manifold) vertex, split\n"
     << "into copies to repair it, has the patch of the copy in the first face (in file\n"
     << "order) that uses it; a vertex that no face uses has -1. For STL, the vertices are\n"
     << "the distinct points in order of first appearance.\n"
     << "\n"
     << "The boundaries are the curves between the patches of the vertices (through the\n"
     << "triangles whose vertices lie in different patches), smoothed in the metric of the\n"
     << "edge weights so that they settle on the features and straighten elsewhere; the\n"
     << "smoothing may move a vertex next to a boundary to the neighbouring patch, which\n"
     << "the patch files and segmentation.ply follow (segmentation_refined.ply: the mesh\n"
     << "cut along the smoothed boundaries, its vertices the mesh's, then the new ones).\n"
     << "\n"
     << "Options:\n"
     << "  --output-dir DIR          output folder, created if needed\n"
     << "                            (default: ./feature_segmentation_output)\n"
     << "  --rings N                 curvature neighbourhood in rings, integer >= 1 (default: 2)\n"
     << "  --radius X                and beyond the rings, the vertices within X times the\n"
     << "                            bounding box diagonal (normals within 30 degrees);\n"
     << "                            0 <= X <= 1, 0: rings only (default: "
     << FS::default_neighborhood_radius << ")\n"
     << "  --strength-threshold X    drop feature lines weaker than X, X >= 0\n"
     << "                            (default: " << FS::default_strength_threshold << ")\n"
     << "  --no-ridges               do not detect ridges\n"
     << "  --no-valleys              do not detect valleys\n"
     << "  --feature-edges FILE      add user feature lines: a CGAL polylines file whose\n"
     << "                            points are mesh vertices and segments mesh edges\n"
     << "  --alpha X                 weight of the feature lines, any finite number; larger\n"
     << "                            gives more patches, useful range 0.5 to 1 (default: "
     << Options().alpha << ")\n"
     << "  --gamma X                 anisotropy of the metric, X >= 0 (default: " << Options().gamma << ")\n"
     << "  --crease-angle D          edges whose faces bend by D degrees or more are creases:\n"
     << "                            the mesh is cut open along them and their sides tied by\n"
     << "                            crease weights (a gap test keeps strong bends of smooth\n"
     << "                            surfaces out); 180 or more: none (with --radius 0,\n"
     << "                            the paper's method)\n"
     << "                            (default: "
     << CGAL::Feature_segmentation::default_crease_angle << ")\n"
     << "  --crease-filter N         rounds of bilateral filtering of the face normals\n"
     << "                            before the creases are found; none on clean meshes;\n"
     << "                            0: raw dihedral angles (default: "
     << CGAL::Feature_segmentation::default_crease_filter_iterations << ")\n"
     << "  --crest-lines-on-clean-tessellations\n"
     << "                            on a CAD tessellation (clean, or cut into pieces by its\n"
     << "                            creases), give the crest lines the full alpha (the\n"
     << "                            paper's features); by default their alpha_e is\n"
     << "                            alpha - 0.5, so that the creases bound the patches at\n"
     << "                            the default alpha\n"
     << "  --no-tangent-discontinuities\n"
     << "                            do not cut clean tessellations along their curvature\n"
     << "                            discontinuities (a fillet meeting a plane without a\n"
     << "                            crease), nor noisy ones along the borders of their\n"
     << "                            planes\n"
     << "  --solver NAME             correlation clustering solver: gaec+klj (greedy additive\n"
     << "                            edge contraction, then Kernighan-Lin with joins),\n"
     << "                            gaec, or klj (from singletons) (default: gaec+klj)\n"
     << "  --full-graph              cluster the full vertex graph, not the reduced graph G'\n"
     << "                            of the watershed oversegmentation (slower)\n"
     << "  --watershed NAME          distance of the watershed oversegmentation: anisotropic\n"
     << "                            (the paper's) or geodesic (default: anisotropic)\n"
     << "  --edits FILE              apply the edit script FILE (below) after the automatic\n"
     << "                            segmentation; the patch outputs are the edited result\n"
     << "  --undo-memory MIB         the most memory the history of edits keeps for undo\n"
     << "                            and redo, in MiB; the oldest states go first, the one\n"
     << "                            before the last edit always stays (default: 256)\n"
     << "  --smoothing-iterations N  iterations of the boundary smoothing, integer >= 0; 0\n"
     << "                            writes the boundaries unsmoothed (default: "
     << default_smoothing_iterations << ")\n"
     << "  --quiet                   no progress or notice lines on stderr (by default every\n"
     << "                            stage prints 'progress: STAGE ...' when it starts and\n"
     << "                            'progress: STAGE done in X s' when it ends)\n"
     << "  --port N                  edit: the port to listen on, 0 .. 65535; 0 picks a free\n"
     << "                            one (default: 8080)\n"
     << "  --host H                  edit: the address to listen on (default: 127.0.0.1;\n"
     << "                            0.0.0.0 opens the editor to the network)\n"
     << "  --web-root DIR            edit: the folder of the editor's page (default: the\n"
     << "                            one installed with the program)\n"
     << "  --no-token                edit: serve the API without the session token that the\n"
     << "                            printed address carries (for scripts on this machine;\n"
     << "                            the Host, Origin and Content-Type checks stay)\n"
     << "  --threads N               threads of the parallel stages (the curvature fits),\n"
     << "                            0 .. 1024; 0: all cores; the result is the same at any\n"
     << "                            count (default: 0)\n"
     << "  --jobs N                  batch: meshes segmented at once, 1 .. 1024 (default: 1)\n"
     << "  --force                   batch: segment again meshes whose outputs are complete\n"
     << "  --help                    the short usage\n"
     << "  --help-all                print this text and exit\n"
     << "\n"
     << "Edit scripts (--edits FILE): one edit per line, applied in order; '#' starts a\n"
     << "comment, blank lines are ignored. Numbers are decimal, finite.\n"
     << "  alpha A                   global refine/coarsen: set alpha to A (the alpha_e of\n"
     << "                            every feature edge moves by A - alpha)\n"
     << "  refine REGION D           local refine: add D to alpha_e on the feature edges\n"
     << "                            of REGION, re-solve the patches it touches\n"
     << "  coarsen REGION D          local coarsen: subtract D from those alpha_e\n"
     << "  scale REGION F            multiply those alpha_e by F >= 0\n"
     << "  merge REGION              merge the patches that REGION touches (kept by later\n"
     << "                            solves)\n"
     << "  sketch [alpha A] X Y Z X Y Z ...\n"
     << "                            a sketched feature line through two points or more,\n"
     << "                            each moved to the nearest point of the surface; the\n"
     << "                            edges it crosses get alpha_e >= A > 1 (default: 2)\n"
     << "  undo                      take back the last edit not yet undone\n"
     << "REGION is 'ball X Y Z R' (the faces whose centroid lies within R > 0 of X Y Z) or\n"
     << "'faces I J ...' (faces of MESH numbered from 0 in file order, as in\n"
     << "face_patches.txt; a triangulated polygon stands for all its triangles). A region\n"
     << "without faces, or a merge inside one patch, changes nothing. A mistake in the\n"
     << "script gives 'error: FILE:LINE: reason' and exit status 1 before the\n"
     << "segmentation runs or anything is written. summary.json lists every edit\n"
     << "(\"edits\"): its line, verb, the patches and cut cost after it, and its seconds\n"
     << "(the library's re-weighting and re-solve; finding the region's faces or locating\n"
     << "the sketch's points apart, as prepare_seconds).\n";
}

} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_PROGRAM_USAGE_H
