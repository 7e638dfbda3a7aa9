// SPDX-License-Identifier: GPL-3.0-or-later
// `feature_segmentation edit MESH`: the interactive editor of the paper (Section 4) as
// a local web page. An HTTP server (cpp-httplib) bound to 127.0.0.1 by default serves
// the page (editor/ in the build: HTML, JavaScript and three.js, nothing fetched at run
// time) and the JSON interface of editor_api.h:
//   GET  /api/state, /api/mesh, /api/labels, /api/features, /api/boundaries?smooth=0|1
//   POST /api/edit   one edit (body: JSON), answered with the new state
//   POST /api/restart  another crest-line scale: {"radius": X, "strength_threshold": T}
//   POST /api/save   writes the outputs and edits.txt into --output-dir
// A refused request gets status 400 and {"error": "..."}; request bodies over 8 MB get
// 413; an unexpected failure 500; the state never changes on an error.

#ifndef CGAL_FEATURE_SEGMENTATION_DEMO_EDITOR_SERVER_H
#define CGAL_FEATURE_SEGMENTATION_DEMO_EDITOR_SERVER_H

#include "editor_api.h"
#include "program_options.h"

#include <httplib.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>

namespace fs_demo {

/// The largest request body the editor reads (a stroke over a million faces fits).
constexpr std::size_t editor_max_body_bytes = 8u << 20;

namespace internal {

// The folder of the editor's page: --web-root, else the one built next to the program
// (FS_EDITOR_WEB_DIR), else share/feature_segmentation/editor beside an installed one.
inline std::filesystem::path editor_web_root(const Options& options)
{
  namespace sfs = std::filesystem;
  std::vector<sfs::path> candidates;
  if(!options.web_root.empty())
    candidates.push_back(options.web_root);
  else
  {
#ifdef FS_EDITOR_WEB_DIR
    candidates.push_back(FS_EDITOR_WEB_DIR);
#endif
    std::error_code ec;
    const sfs::path exe = sfs::read_symlink("/proc/self/exe", ec);
    if(!ec) candidates.push_back(exe.parent_path().parent_path() / "share" / "feature_segmentation" / "editor");
  }
  for(const sfs::path& p : candidates)
    if(sfs::is_regular_file(p / "index.html") && sfs::is_regular_file(p / "three.module.min.js"))
      return p;
  std::string tried;
  for(const sfs::path& p : candidates) tried += (tried.empty() ? "" : ", ") + p.string();
  throw std::runtime_error("the editor's web page is not found (looked in " + tried +
                           "; build the program with npm available, or pass --web-root DIR)");
}

inline void send_json(httplib::Response& res, const std::string& body, int status = 200)
{
  res.status = status;
  res.set_header("Cache-Control", "no-store");
  res.set_content(body, "application/json");
}

inline void send_error(httplib::Response& res, int status, const std::string& what)
{
  send_json(res, nlohmann::json{{"error", what}}.dump(), status);
}

// Parses the body as JSON and answers with `call(body)`; 400 for bad JSON or a request
// that `call` refuses.
template <typename Call>
void answer_json_request(const httplib::Request& req, httplib::Response& res, Call call)
{
  nlohmann::json request;
  try
  {
    request = nlohmann::json::parse(req.body);
  }
  catch(const nlohmann::json::exception& e)
  {
    return send_error(res, 400, std::string("the request is not valid JSON: ") + e.what());
  }
  try
  {
    send_json(res, call(request).dump());
  }
  catch(const Request_error& e)
  {
    send_error(res, 400, e.what());
  }
}

} // namespace internal

/// Configures `server` to serve `session` and the page in `web_root`.
inline void configure_editor_server(httplib::Server& server, Editor_session& session,
                                    const std::filesystem::path& web_root)
{
  using internal::send_error;
  using internal::send_json;
  server.set_payload_max_length(editor_max_body_bytes);
  server.set_read_timeout(10, 0);
  server.set_write_timeout(30, 0);
  if(!server.set_mount_point("/", web_root.string()))
    throw std::runtime_error(web_root.string() + ": cannot serve the editor's page from this folder");
  server.set_file_extension_and_mimetype_mapping("js", "text/javascript");

  server.Get("/api/state", [&](const httplib::Request&, httplib::Response& res) {
    send_json(res, session.state().dump());
  });
  server.Get("/api/mesh", [&](const httplib::Request&, httplib::Response& res) { send_json(res, session.mesh()); });
  server.Get("/api/labels", [&](const httplib::Request&, httplib::Response& res) {
    send_json(res, session.labels());
  });
  server.Get("/api/features", [&](const httplib::Request&, httplib::Response& res) {
    send_json(res, session.features());
  });
  server.Get("/api/boundaries", [&](const httplib::Request& req, httplib::Response& res) {
    const std::string smooth = req.has_param("smooth") ? req.get_param_value("smooth") : "1";
    if(smooth != "0" && smooth != "1")
      return send_error(res, 400, "boundaries: 'smooth' must be 0 or 1");
    send_json(res, session.boundaries(smooth == "1"));
  });
  server.Post("/api/edit", [&](const httplib::Request& req, httplib::Response& res) {
    internal::answer_json_request(req, res, [&](const nlohmann::json& j) { return session.edit(j); });
  });
  server.Post("/api/restart", [&](const httplib::Request& req, httplib::Response& res) {
    internal::answer_json_request(req, res, [&](const nlohmann::json& j) { return session.restart(j); });
  });
  server.Post("/api/save", [&](const httplib::Request&, httplib::Response& res) {
    send_json(res, session.save().dump());
  });
  server.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr ep) {
    std::string what = "unknown error";
    try { std::rethrow_exception(ep); }
    catch(const std::bad_alloc&) { what = "out of memory"; }
    catch(const std::exception& e) { what = e.what(); }
    catch(...) {}
    send_error(res, 500, what);
  });
  server.set_error_handler([](const httplib::Request&, httplib::Response& res) {
    if(res.status == 413)
      send_error(res, 413, "the request body is larger than " + std::to_string(editor_max_body_bytes) + " bytes");
    else if(res.body.empty())
      send_error(res, res.status,
                 res.status == 404   ? "no such resource"
                 : res.status == 400 ? "bad request (a POST needs a body with its Content-Length)"
                                     : "HTTP error " + std::to_string(res.status));
  });
}

/// Runs the editor until the process is stopped.
inline int run_editor(const Options& options)
{
  const std::filesystem::path web_root = internal::editor_web_root(options);
  Editor_session session(options);
  httplib::Server server;
  configure_editor_server(server, session, web_root);
  const int port = options.port == 0 ? server.bind_to_any_port(options.host)
                                     : (server.bind_to_port(options.host, options.port) ? options.port : -1);
  if(port < 0)
    throw std::runtime_error("cannot listen on " + options.host + ":" + std::to_string(options.port) +
                             " (in use, or not an address of this machine)");
  const bool ipv6 = options.host.find(':') != std::string::npos;
  if(options.host != "127.0.0.1" && options.host != "localhost" && options.host != "::1")
    std::cerr << "notice: --host " << options.host
              << ": the editor (which writes into " << options.output_dir
              << ") is open to other machines; it has no password" << std::endl;
  std::cout << "editor: http://" << (ipv6 ? "[" + options.host + "]" : options.host) << ":" << port << "/"
            << std::endl;
  if(!server.listen_after_bind())
    throw std::runtime_error("the editor's server stopped unexpectedly");
  return EXIT_SUCCESS;
}

} // namespace fs_demo

#endif // CGAL_FEATURE_SEGMENTATION_DEMO_EDITOR_SERVER_H
