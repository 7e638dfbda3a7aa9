// SPDX-License-Identifier: GPL-3.0-or-later
// `feature_segmentation edit MESH`: the interactive editor of the paper (Section 4) as
// a local web page. An HTTP server (cpp-httplib) bound to 127.0.0.1 by default serves
// the page (editor/ in the build: HTML, JavaScript and three.js, nothing fetched at run
// time) and the JSON interface of editor_api.h:
//   GET  /api/state, /api/mesh, /api/labels, /api/features, /api/boundaries?smooth=0|1,
//        /api/history?from=K&count=N
//   POST /api/edit   one edit (body: JSON), answered with the new state
//   POST /api/restart  another crest-line scale: {"radius": X, "strength_threshold": T}
//   POST /api/save   writes the outputs and edits.txt into --output-dir
// A refused request gets status 400 and {"error": "..."}; request bodies over 8 MB get
// 413; an unexpected failure 500; the state never changes on an error.
// Only the user can drive it: every request must name this server in its Host header
// (localhost, 127.0.0.1, [::1] or --host, at its port: a DNS-rebinding page cannot), every
// API request must carry the session token (random per start, in the address the
// program prints; the page sends it as the X-Editor-Token header and as a cookie), a POST
// must be application/json (so a cross-site request needs a preflight, which fails) from
// no other Origin, and chunked bodies are refused (the size limit needs the length).
// Reads time out after 5 s, and 32 threads serve the connections.

#ifndef CGAL_FEATURE_SEGMENTATION_DEMO_EDITOR_SERVER_H
#define CGAL_FEATURE_SEGMENTATION_DEMO_EDITOR_SERVER_H

#include "editor_api.h"
#include "program_options.h"

#include <httplib.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace fs_demo {

/// The largest request body the editor reads (a stroke over a million faces fits).
constexpr std::size_t editor_max_body_bytes = 8u << 20;

/// Who may use the editor: the session token (empty: none is asked, `--no-token`), the
/// host names the server answers to, and its port (known once it is bound).
struct Editor_access
{
  std::string token;
  std::vector<std::string> hosts = {"localhost", "127.0.0.1", "[::1]"};
  int port = 0;

  /// A Host header naming this server: one of `hosts`, at `port` or without a port.
  bool is_allowed_host(const std::string& header) const
  {
    std::string host = header;
    std::transform(host.begin(), host.end(), host.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    const std::size_t colon = host.rfind(':');
    if(colon != std::string::npos && host.find(']', colon) == std::string::npos)
    {
      if(host.substr(colon + 1) != std::to_string(port)) return false;
      host.erase(colon);
    }
    return std::find(hosts.begin(), hosts.end(), host) != hosts.end();
  }
  /// An Origin header of this server's pages: http://HOST:PORT with an allowed HOST.
  bool is_allowed_origin(const std::string& origin) const
  {
    const std::string scheme = "http://";
    return origin.rfind(scheme, 0) == 0 && origin.find(':', scheme.size()) != std::string::npos &&
           origin.find('/', scheme.size()) == std::string::npos && is_allowed_host(origin.substr(scheme.size()));
  }
  /// Whether the request carries the token (X-Editor-Token header, or the fs_editor_token cookie).
  bool has_token(const httplib::Request& req) const
  {
    if(token.empty()) return true;
    if(same(req.get_header_value("X-Editor-Token"), token)) return true;
    std::istringstream cookies(req.get_header_value("Cookie"));
    std::string cookie;
    while(std::getline(cookies, cookie, ';'))
    {
      cookie.erase(0, cookie.find_first_not_of(' '));
      if(cookie.rfind("fs_editor_token=", 0) == 0 && same(cookie.substr(16), token)) return true;
    }
    return false;
  }

private:
  // compares in a time that does not depend on where the two differ
  static bool same(const std::string& a, const std::string& b)
  {
    if(a.size() != b.size()) return false;
    unsigned char d = 0;
    for(std::size_t i = 0; i < a.size(); ++i) d |= static_cast<unsigned char>(a[i] ^ b[i]);
    return d == 0;
  }
};

/// A random session token: 128 bits from the system's random source, in hexadecimal.
inline std::string random_editor_token()
{
  std::random_device source; // /dev/urandom on Linux
  std::ostringstream text;
  for(int i = 0; i < 4; ++i)
  {
    const std::uint32_t x = source();
    const char* digits = "0123456789abcdef";
    for(int k = 28; k >= 0; k -= 4) text << digits[(x >> k) & 15u];
  }
  return text.str();
}

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

/// Configures `server` to serve `session` and the page in `web_root` to the requests that
/// `access` lets through (read when a request comes: its port may be set after binding).
inline void configure_editor_server(httplib::Server& server, Editor_session& session,
                                    const std::filesystem::path& web_root, const Editor_access& access)
{
  using internal::send_error;
  using internal::send_json;
  server.set_payload_max_length(editor_max_body_bytes);
  server.set_read_timeout(5, 0);
  server.set_write_timeout(30, 0);
  server.set_keep_alive_timeout(5);
  // more workers than slow clients one user's machine can be expected to hold open
  server.new_task_queue = [] { return new httplib::ThreadPool(32); };
  server.set_pre_routing_handler([&access](const httplib::Request& req, httplib::Response& res) {
    res.set_header("X-Content-Type-Options", "nosniff");
    res.set_header("X-Frame-Options", "DENY");
    res.set_header("Content-Security-Policy", "frame-ancestors 'none'");
    res.set_header("Referrer-Policy", "no-referrer"); // the token is in the page's address
    const auto refuse = [&res](int status, const std::string& why) {
      res.set_header("Connection", "close"); // what is left of the request is not read
      send_error(res, status, why);
      return httplib::Server::HandlerResponse::Handled;
    };
    if(!access.is_allowed_host(req.get_header_value("Host")))
      return refuse(403, "the Host header '" + req.get_header_value("Host").substr(0, 100) +
                           "' does not name this editor (open the address the program printed)");
    if(req.has_header("Transfer-Encoding"))
      return refuse(411, "chunked request bodies are not accepted: send the body with its Content-Length");
    if(req.path.rfind("/api/", 0) != 0) return httplib::Server::HandlerResponse::Unhandled; // the page's files
    if(!access.has_token(req))
      return refuse(401, "missing or wrong session token: open the address the program printed (it ends with ?token=...)");
    if(req.method == "POST")
    {
      if(req.has_header("Origin") && !access.is_allowed_origin(req.get_header_value("Origin")))
        return refuse(403, "requests from the page at " + req.get_header_value("Origin").substr(0, 100) +
                             " are not accepted");
      const std::string type = req.get_header_value("Content-Type");
      if(type.rfind("application/json", 0) != 0)
        return refuse(415, "a POST must have Content-Type: application/json (got '" + type.substr(0, 100) + "')");
    }
    return httplib::Server::HandlerResponse::Unhandled;
  });
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
  server.Get("/api/history", [&](const httplib::Request& req, httplib::Response& res) {
    std::size_t number[2] = {0, 50};
    const char* names[2] = {"from", "count"};
    for(int k = 0; k < 2; ++k)
    {
      if(!req.has_param(names[k])) continue;
      const std::string text = req.get_param_value(names[k]);
      if(text.empty() || text.size() > 9 || text.find_first_not_of("0123456789") != std::string::npos)
        return send_error(res, 400, std::string("history: '") + names[k] + "' must be an integer >= 0");
      number[k] = std::stoul(text);
    }
    try
    {
      send_json(res, session.history(number[0], number[1]).dump());
    }
    catch(const Request_error& e)
    {
      send_error(res, 400, e.what());
    }
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
                 : res.status == 400 ? "bad request: malformed HTTP, or a POST without its Content-Length"
                                     : "HTTP error " + std::to_string(res.status));
  });
}

/// Runs the editor until the process is stopped.
inline int run_editor(const Options& options)
{
  const std::filesystem::path web_root = internal::editor_web_root(options);
  Editor_session session(options);
  httplib::Server server;
  Editor_access access;
  if(!options.no_token) access.token = random_editor_token();
  const bool ipv6 = options.host.find(':') != std::string::npos;
  const std::string host_name = ipv6 ? "[" + options.host + "]" : options.host;
  std::string lower = host_name;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  access.hosts.push_back(lower);
  configure_editor_server(server, session, web_root, access);
  const int port = options.port == 0 ? server.bind_to_any_port(options.host)
                                     : (server.bind_to_port(options.host, options.port) ? options.port : -1);
  if(port < 0)
    throw std::runtime_error("cannot listen on " + options.host + ":" + std::to_string(options.port) +
                             " (in use, or not an address of this machine)");
  access.port = port; // before the first request is served
  if(options.host != "127.0.0.1" && options.host != "localhost" && options.host != "::1")
    std::cerr << "notice: --host " << options.host << ": the editor (which writes into " << options.output_dir
              << ") is open to other machines" << (options.no_token ? " without a token" : ", to whoever has its token")
              << std::endl;
  if(options.no_token)
    std::cerr << "notice: --no-token: any program or page that reaches " << host_name << ":" << port
              << " can drive the editor (only JSON requests naming this host are accepted)" << std::endl;
  std::cout << "editor: http://" << host_name << ":" << port << "/"
            << (access.token.empty() ? std::string() : "?token=" + access.token) << std::endl;
  if(!server.listen_after_bind())
    throw std::runtime_error("the editor's server stopped unexpectedly");
  return EXIT_SUCCESS;
}

} // namespace fs_demo

#endif // CGAL_FEATURE_SEGMENTATION_DEMO_EDITOR_SERVER_H
