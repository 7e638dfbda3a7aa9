// SPDX-License-Identifier: GPL-3.0-or-later
// `feature_segmentation edit MESH`: the interactive editor of the paper (Section 4) as
// a local web page. An event-driven HTTP server (Boost.Beast on one Asio thread, the
// edits on two worker threads) bound to 127.0.0.1 by default serves the page (editor/ in
// the build: HTML, JavaScript and three.js, read into memory at start, nothing fetched at
// run time) and the JSON interface of editor_api.h:
//   GET  /api/state, /api/mesh?format=json|binary, /api/labels?format=json|binary|runs,
//        /api/features, /api/boundaries?smooth=0|1,
//        /api/history?from=K&count=N
//   POST /api/edit   one edit (body: JSON), answered with the new state
//        (?labels=binary or runs: with the state and the labels in one message)
//   POST /api/restart  another crest-line scale: {"radius": X, "strength_threshold": T}
//   POST /api/save   writes the outputs and edits.txt into --output-dir
// A refused request gets a 4xx status and {"error": "..."} naming the fault (400 a bad
// request, 403 the token, Host or Origin, 413 a body over 8 MB, chunked or not, 415
// the content type, 431 headers over 16 KB); an unexpected failure 500; the state never
// changes on an error.
// Only the user can drive it: every request must name this server in its Host header
// (localhost, 127.0.0.1, [::1] or --host, at its port: a DNS-rebinding page cannot), every
// API request must carry the session token (random per start, in the address the
// program prints; the page sends it as the X-Editor-Token header and as a cookie), and a
// POST must be application/json (so a cross-site request needs a preflight, which fails)
// from no other Origin. These checks run on the headers, before any body is read.
// Slow clients cost memory, not workers: a request's headers must arrive within 10 s of
// the connection's turn to speak (its opening or its previous answer), its body within
// 30 s more; at most 1024 connections are open at once.


#ifndef CGAL_FEATURE_SEGMENTATION_APP_EDITOR_SERVER_H
#define CGAL_FEATURE_SEGMENTATION_APP_EDITOR_SERVER_H

#include "editor_http.h"


#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/signal_set.hpp>
#include <boost/asio/thread_pool.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace fs_app {
namespace internal {

class Editor_http_server;

// One connection: headers (checked), then the body, then the answer computed on a
// worker, written back; again while the client keeps the connection alive.
class Editor_connection : public std::enable_shared_from_this<Editor_connection>
{
public:
  Editor_connection(tcp::socket socket, Editor_http_server& server, std::atomic<int>& open)
      : m_stream(std::move(socket)), m_server(server), m_open(open)
  {
    ++m_open;
  }
  ~Editor_connection() { --m_open; }
  inline void start() { read_header(); }

private:
  inline void read_header();
  inline void on_header(beast::error_code ec);
  inline void read_body();
  inline void on_body(beast::error_code ec);
  inline void fail(beast::error_code ec);
  inline void write(Http_answer answer, bool keep_alive);
  inline void drain();

  beast::tcp_stream m_stream;
  beast::flat_buffer m_buffer;
  std::optional<http::request_parser<http::string_body>> m_parser;
  http::response<http::string_body> m_response;
  std::array<char, 8 * 1024> m_scratch;
  std::size_t m_discarded = 0;
  Editor_http_server& m_server;
  std::atomic<int>& m_open;
};

/// The editor's HTTP server: one Asio thread for the connections, two workers for the
/// answers (the session lets one edit run at a time).
class Editor_http_server
{
public:
  Editor_http_server(Editor_session& session, std::map<std::string, Page_file> page, const Editor_access& access,
                     Editor_server_limits limits = {})
      : m_session(session), m_page(std::move(page)), m_access(access), m_limits(limits), m_acceptor(m_io),
        m_retry(m_io)
  {}

  /// Listens on `host`:`port` (0: a free port) and answers with the port.
  /// \throws std::runtime_error if it cannot
  int listen(const std::string& host, int port)
  {
    beast::error_code ec;
    tcp::resolver resolver(m_io);
    const auto endpoints = resolver.resolve(host, std::to_string(port), tcp::resolver::passive, ec);
    if(ec || endpoints.empty())
      throw std::runtime_error("cannot listen on " + host + ":" + std::to_string(port) + " (" + ec.message() + ")");
    const tcp::endpoint endpoint = endpoints.begin()->endpoint();
    m_acceptor.open(endpoint.protocol(), ec);
    if(!ec) m_acceptor.set_option(net::socket_base::reuse_address(true), ec);
    if(!ec) m_acceptor.bind(endpoint, ec);
    if(!ec) m_acceptor.listen(net::socket_base::max_listen_connections, ec);
    if(ec)
      throw std::runtime_error("cannot listen on " + host + ":" + std::to_string(port) + " (" + ec.message() +
                               ": in use, or not an address of this machine)");
    return m_acceptor.local_endpoint().port();
  }

  /// Serves until the process is stopped.
  void run()
  {
    accept();
    m_io.run();
  }

  const Editor_server_limits& limits() const { return m_limits; }
  std::optional<Http_answer> refuse(const http::request_header<>& h) const
  {
    return refuse_by_headers(h, m_access);
  }
  /// Computes the answer to `req` on a worker, then calls `done(answer)` on the
  /// connections' thread.
  template <typename Done>
  void answer(http::request<http::string_body> req, Done done)
  {
    net::post(m_workers, [this, req = std::move(req), done = std::move(done)]() mutable {
      Http_answer a = answer_request(req, m_session, m_page);
      net::post(m_io, [a = std::move(a), done = std::move(done)]() mutable { done(std::move(a)); });
    });
  }

private:
  void accept()
  {
    m_acceptor.async_accept(m_io, [this](beast::error_code ec, tcp::socket socket) {
      if(ec)
      {
        // out of file descriptors, most likely: try again shortly rather than spin
        m_retry.expires_after(std::chrono::milliseconds(50));
        m_retry.async_wait([this](beast::error_code) { accept(); });
        return;
      }
      if(m_open.load() < m_limits.connections)
        std::make_shared<Editor_connection>(std::move(socket), *this, m_open)->start();
      accept(); // a socket over the limit is closed as it goes out of scope
    });
  }

  Editor_session& m_session;
  std::map<std::string, Page_file> m_page;
  const Editor_access& m_access;
  Editor_server_limits m_limits;
  net::io_context m_io{1};
  tcp::acceptor m_acceptor;
  net::steady_timer m_retry;
  net::thread_pool m_workers{2};
  std::atomic<int> m_open{0};
};

void Editor_connection::read_header()
{
  m_parser.emplace();
  m_parser->header_limit(static_cast<std::uint32_t>(m_server.limits().header_bytes));
  m_parser->body_limit(m_server.limits().body_bytes); // chunked bodies too
  m_stream.expires_after(m_server.limits().header_time);
  http::async_read_header(m_stream, m_buffer, *m_parser,
                          [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_header(ec); });
}

void Editor_connection::on_header(beast::error_code ec)
{
  if(ec) return fail(ec);
  if(auto refusal = m_server.refuse(m_parser->get())) return write(std::move(*refusal), false);
  if(m_parser->get()[http::field::expect] == "100-continue")
  {
    static const std::string go_on = "HTTP/1.1 100 Continue\r\n\r\n";
    m_stream.expires_after(m_server.limits().write_time);
    return net::async_write(m_stream, net::buffer(go_on), [self = shared_from_this()](beast::error_code e, std::size_t) {
      if(e) return self->fail(e);
      self->read_body();
    });
  }
  read_body();
}

void Editor_connection::read_body()
{
  m_stream.expires_after(m_server.limits().body_time);
  http::async_read(m_stream, m_buffer, *m_parser,
                   [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_body(ec); });
}

void Editor_connection::on_body(beast::error_code ec)
{
  if(ec) return fail(ec);
  m_stream.expires_never(); // an edit may take a while; the client waits
  http::request<http::string_body> req = m_parser->release();
  const bool keep_alive = req.keep_alive();
  m_server.answer(std::move(req), [self = shared_from_this(), keep_alive](Http_answer a) {
    self->write(std::move(a), keep_alive);
  });
}

void Editor_connection::fail(beast::error_code ec)
{
  // a request the parser refuses is told why; a closed, silent or slow connection is dropped
  if(ec == http::error::body_limit)
    return write(error_answer(http::status::payload_too_large, "the request body is larger than " +
                                                                 std::to_string(m_server.limits().body_bytes) + " bytes", true),
                 false);
  if(ec == http::error::header_limit)
    return write(error_answer(http::status::request_header_fields_too_large,
                              "the request's headers are larger than " + std::to_string(m_server.limits().header_bytes) +
                                " bytes", true),
                 false);
  if(ec.category() == beast::error_code(http::error::end_of_stream).category() && ec != http::error::end_of_stream &&
     ec != http::error::partial_message)
    return write(error_answer(http::status::bad_request, "malformed HTTP request: " + ec.message(), true), false);
}

void Editor_connection::drain()
{
  // after an answer that leaves the request unread, what the client still sends is read and
  // dropped for a while (2 s, 64 MB): closing at once would reset the connection, and the
  // client could lose the answer
  if(m_discarded > (64u << 20)) return;
  m_stream.async_read_some(net::buffer(m_scratch), [self = shared_from_this()](beast::error_code ec, std::size_t n) {
    if(ec) return;
    self->m_discarded += n;
    self->drain();
  });
}

void Editor_connection::write(Http_answer answer, bool keep_alive)
{
  m_response = {};
  m_response.version(11);
  m_response.result(answer.status);
  m_response.set(http::field::content_type, answer.type);
  m_response.set(http::field::cache_control, "no-store");
  m_response.set("X-Content-Type-Options", "nosniff");
  m_response.set("X-Frame-Options", "DENY");
  m_response.set("Content-Security-Policy", "frame-ancestors 'none'");
  m_response.set("Referrer-Policy", "no-referrer"); // the token is in the page's address
  if(answer.status == http::status::method_not_allowed) m_response.set(http::field::allow, "GET, POST");
  m_response.body() = std::move(answer.body);
  m_response.keep_alive(keep_alive && !answer.close);
  m_response.prepare_payload();
  m_stream.expires_after(m_server.limits().write_time);
  http::async_write(m_stream, m_response, [self = shared_from_this()](beast::error_code ec, std::size_t) {
    if(ec) return;
    if(!self->m_response.keep_alive())
    {
      beast::error_code ignored;
      self->m_stream.socket().shutdown(tcp::socket::shutdown_send, ignored);
      self->m_discarded = 0;
      self->m_stream.expires_after(std::chrono::seconds(2));
      return self->drain();
    }
    self->read_header();
  });
}

} // namespace internal

/// Runs the editor until the process is stopped.
inline int run_editor(const Options& options)
{
  Editor_access access;
  if(!options.no_token) access.token = random_editor_token();
  const bool ipv6 = options.host.find(':') != std::string::npos;
  const std::string host_name = ipv6 ? "[" + options.host + "]" : options.host;
  std::string lower = host_name;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  access.hosts.push_back(lower);
  auto page = internal::read_editor_page(internal::editor_web_root(options));
  Editor_session session(options);
  internal::Editor_http_server server(session, std::move(page), access);
  access.port = server.listen(options.host, options.port); // before the first request is served
  if(options.host != "127.0.0.1" && options.host != "localhost" && options.host != "::1")
    std::cerr << "notice: --host " << options.host << ": the editor (which writes into " << options.output_dir
              << ") is open to other machines" << (options.no_token ? " without a token" : ", to whoever has its token")
              << std::endl;
  if(options.no_token)
    std::cerr << "notice: --no-token: any program or page that reaches " << host_name << ":" << access.port
              << " can drive the editor (only JSON requests naming this host are accepted)" << std::endl;
  std::cout << "editor: http://" << host_name << ":" << access.port << "/"
            << (access.token.empty() ? std::string() : "?token=" + access.token) << std::endl;
  server.run();
  return EXIT_SUCCESS;
}

} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_EDITOR_SERVER_H
