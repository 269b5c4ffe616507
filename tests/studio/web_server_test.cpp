// The studio's server over real sockets (studio_app.h, web_server.h): the page's files, the three
// WebSockets, and hostile peers (a malformed message on each socket, a binary frame, an oversized
// frame, a flood, a peer gone mid-download of the page or of a program, a path outside the
// page): each is answered or dropped, the drive goes on and the stored program stays.
#include <gtest/gtest.h>

#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <filesystem>
#include <fstream>
#include <future>
#include <thread>
#include <utility>  // before Beast (transport/asio.h)

#include "dialect/dl_lines.h"
#include "dialects/registry.h"
#include "studio/studio_app.h"
#include "support/files.h"

namespace uprog::studio {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;
using nlohmann::json;

// A studio on a free loopback port, its io_context on a thread of its own.
class Server {
 public:
  explicit Server(WebLimits limits = {}) {
    folder_ = std::filesystem::temp_directory_path() /
              ("uprog_studio_test_" + std::to_string(::getpid()) + "_" + std::to_string(++count_));
    std::filesystem::create_directories(folder_);
    std::ofstream(folder_ / "index.html") << "<!doctype html><title>uprog studio</title>";
    std::ofstream big(folder_ / "big.js");
    big << std::string(8 << 20, 'x');  // larger than any socket buffer
    big.close();
    StudioOptions options;
    options.drive.dialect = dialects::find("gold");
    options.drive.file = "first_move.ehl";
    options.drive.source =
        *read_text_file(std::string(UPROG_SOURCE_DIR) + "/examples/gold/first_move.ehl");
    const auto all = dialects::all();
    options.dialects.assign(all.begin(), all.end());
    options.page_folder = folder_.string();
    options.endpoint = tcp::endpoint(asio::ip::make_address("127.0.0.1"), 0);
    options.limits = limits;
    app_ = std::make_unique<StudioApp>(io_, options);
    port_ = app_->local_endpoint().port();
    thread_ = std::thread([this] { io_.run(); });
  }
  ~Server() {
    asio::post(io_, [this] {
      app_->stop();
      io_.stop();
    });
    thread_.join();
    app_.reset();
    std::filesystem::remove_all(folder_);
  }
  uint16_t port() const { return port_; }
  // The drive's virtual time, read on the server's thread.
  uint64_t now_us() {
    std::promise<uint64_t> p;
    asio::post(io_, [&] { p.set_value(app_->drive().controller().now_us()); });
    return p.get_future().get();
  }

 private:
  static inline int count_ = 0;
  std::filesystem::path folder_;
  asio::io_context io_;
  std::unique_ptr<StudioApp> app_;
  uint16_t port_ = 0;
  std::thread thread_;
};

struct Client {
  Client(uint16_t port, const std::string& path) : ws(io) {
    beast::get_lowest_layer(ws).connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), port));
    ws.handshake("127.0.0.1", path);
  }
  void send(const std::string& text) { ws.write(asio::buffer(text)); }
  // The next text message parsed; a null json when the connection ended (`error` says how).
  json read() {
    beast::flat_buffer buffer;
    do {
      buffer.clear();
      ws.read(buffer, error);
      if (error) return nullptr;
    } while (!ws.got_text());  // scope samples are binary
    return json::parse(beast::buffers_to_string(buffer.data()));
  }
  json read_type(const std::string& type) {
    for (json m = read(); !m.is_null(); m = read()) {
      if (m["type"] == type || m.value("method", "") == type || m.value("event", "") == type)
        return m;
    }
    return nullptr;
  }
  asio::io_context io;
  websocket::stream<beast::tcp_stream> ws;
  beast::error_code error;
};

http::response<http::string_body> get(uint16_t port, const std::string& target) {
  asio::io_context io;
  beast::tcp_stream stream(io);
  stream.connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), port));
  http::request<http::empty_body> request(http::verb::get, target, 11);
  request.set(http::field::host, "127.0.0.1");
  http::write(stream, request);
  beast::flat_buffer buffer;
  http::response_parser<http::string_body> parser;
  parser.body_limit(64 << 20);
  http::read(stream, buffer, parser);
  return parser.release();
}

TEST(StudioServer, ServesThePageAndNothingOutsideIt) {
  Server server;
  const auto page = get(server.port(), "/");
  EXPECT_EQ(page.result(), http::status::ok);
  EXPECT_EQ(page.body(), "<!doctype html><title>uprog studio</title>");
  EXPECT_EQ(page[http::field::content_type], "text/html; charset=utf-8");
  EXPECT_EQ(get(server.port(), "/../../etc/passwd").result(), http::status::not_found);
  EXPECT_EQ(get(server.port(), "/nothing.js").result(), http::status::not_found);
  EXPECT_EQ(get(server.port(), "/ws/nowhere").result(), http::status::not_found);
}

TEST(StudioServer, ARequestHeadTooLargeIsRefused) {
  Server server;
  asio::io_context io;
  beast::tcp_stream stream(io);
  stream.connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), server.port()));
  http::request<http::empty_body> request(http::verb::get, "/", 11);
  request.set("X-Padding", std::string(40 * 1024, 'a'));
  beast::error_code ec;
  http::write(stream, request, ec);
  beast::flat_buffer buffer;
  http::response<http::string_body> response;
  http::read(stream, buffer, response, ec);
  if (!ec) {
    EXPECT_EQ(response.result(), http::status::payload_too_large);
  }
  EXPECT_EQ(get(server.port(), "/").result(), http::status::ok);  // and the server goes on
}

TEST(StudioServer, AClientGoneMidDownloadLeavesTheServerServing) {
  Server server;
  for (int i = 0; i < 3; ++i) {
    asio::io_context io;
    tcp::socket socket(io);
    socket.connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), server.port()));
    const std::string request = "GET /big.js HTTP/1.1\r\nHost: x\r\n\r\n";
    asio::write(socket, asio::buffer(request));
    char head[1024];
    socket.read_some(asio::buffer(head));
    socket.close();  // 8 MB announced, 1 KB read
  }
  const auto big = get(server.port(), "/big.js");
  EXPECT_EQ(big.body().size(), size_t{8} << 20);
  const uint64_t before = server.now_us();
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_GT(server.now_us(), before);  // the drive's time goes on
}

TEST(StudioServer, TheDriveSocketSaysHelloAndAnswersAMalformedMessage) {
  Server server;
  Client c(server.port(), "/ws/drive");
  const json hello = c.read();
  EXPECT_EQ(hello["type"], "hello");
  EXPECT_EQ(hello["dialect"], "gold");
  c.send("{ this is not json");
  EXPECT_EQ(c.read_type("error")["message"], "not a JSON object");
  c.send(json({{"op", "line"}, {"text", "1+1"}}).dump());
  EXPECT_EQ(c.read_type("answers")["answers"][0]["text"], "2");
}

TEST(StudioServer, AnOversizedFrameClosesWith1009AndOthersGoOn) {
  WebLimits limits;
  limits.max_message_bytes = 64 * 1024;
  Server server(limits);
  {
    Client c(server.port(), "/ws/drive");
    c.read();
    // The server may close before the client has written the whole frame (its write then fails
    // with a broken pipe or a reset); else the client reads the close frame, 1009.
    beast::error_code write_error;
    c.ws.write(asio::buffer(std::string(100 * 1024, ' ')), write_error);
    if (!write_error) {
      while (!c.read().is_null()) {
      }
      EXPECT_EQ(c.ws.reason().code, websocket::close_code::too_big) << c.error.message();
    } else {
      EXPECT_TRUE(write_error == asio::error::broken_pipe ||
                  write_error == asio::error::connection_reset)
          << write_error.message();
    }
  }
  Client d(server.port(), "/ws/drive");
  EXPECT_EQ(d.read()["type"], "hello");
}

// A flood of terminal lines from a peer that reads nothing meanwhile: every line is answered, in
// order, or (past the unread limit) the peer is dropped; the drive's time goes on either way.
TEST(StudioServer, AFloodIsAnsweredOrDroppedAndTheDriveGoesOn) {
  WebLimits limits;
  limits.max_unread_bytes = 256 * 1024;
  Server server(limits);
  constexpr int kLines = 3000;
  int answered = 0;
  bool dropped = false;
  {
    Client c(server.port(), "/ws/drive");
    c.read();
    beast::get_lowest_layer(c.ws).socket().set_option(
        asio::socket_base::receive_buffer_size(65536));
    for (int i = 0; i < kLines; ++i) {
      c.send(json({{"op", "line"}, {"text", std::to_string(i) + "+0"}}).dump());
      if (c.error) break;
    }
    while (answered < kLines) {
      const json m = c.read();
      if (m.is_null()) {
        dropped = true;
        break;
      }
      if (m["type"] != "answers") continue;
      EXPECT_EQ(m["answers"][0]["text"], std::to_string(answered));
      ++answered;
    }
  }
  EXPECT_TRUE(answered == kLines || dropped);
  const uint64_t before = server.now_us();
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_GT(server.now_us(), before);
  Client d(server.port(), "/ws/drive");
  EXPECT_EQ(d.read()["type"], "hello");
}

// A page that asks for 8 channels as fast as the drive goes and reads nothing is dropped once the
// unread samples pass the limit, instead of growing the server's memory; the drive goes on.
TEST(StudioServer, APeerThatDoesNotReadIsDropped) {
  WebLimits limits;
  limits.max_unread_bytes = 64 * 1024;
  Server server(limits);
  {
    Client c(server.port(), "/ws/drive");
    beast::get_lowest_layer(c.ws).socket().set_option(asio::socket_base::receive_buffer_size(4096));
    c.send(json({{"op", "scope"},
                 {"channels", {"PX", "VX", "PE", "IQ", "MS", "DV[1]", "DV[2]", "DV[3]"}}})
               .dump());
    c.send(json({{"op", "speed"}, {"factor", "max"}}).dump());
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    // Kept, the stream would go on without end; dropped, it ends with what was in flight.
    beast::flat_buffer buffer;
    size_t read_bytes = 0;
    while (!c.error && read_bytes < (size_t{64} << 20)) {
      buffer.clear();
      read_bytes += c.ws.read(buffer, c.error);
    }
    EXPECT_NE(c.error, beast::error_code{});
    EXPECT_LT(read_bytes, size_t{64} << 20);
  }
  const uint64_t before = server.now_us();
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_GT(server.now_us(), before);
  Client d(server.port(), "/ws/drive");
  EXPECT_EQ(d.read()["type"], "hello");
}

TEST(StudioServer, TheLanguageServerAnswersOverItsSocket) {
  Server server;
  Client c(server.port(), "/ws/lsp");
  c.send(json({{"jsonrpc", "2.0"},
               {"id", 1},
               {"method", "initialize"},
               {"params", {{"capabilities", json::object()}}}})
             .dump());
  const json init = c.read();
  EXPECT_EQ(init["id"], 1);
  EXPECT_TRUE(init["result"].contains("capabilities"));
  c.send(json({{"jsonrpc", "2.0"}, {"method", "initialized"}, {"params", json::object()}}).dump());
  // A line that does not parse: its diagnostic is on that line.
  c.send(json({{"jsonrpc", "2.0"},
               {"method", "textDocument/didOpen"},
               {"params",
                {{"textDocument",
                  {{"uri", "file:///studio/first_move.ehl"},
                   {"languageId", "gold"},
                   {"version", 1},
                   {"text", "function main()\nx = = 1\nreturn\n"}}}}}})
             .dump());
  const json diagnostics = c.read_type("textDocument/publishDiagnostics");
  ASSERT_FALSE(diagnostics.is_null());
  ASSERT_FALSE(diagnostics["params"]["diagnostics"].empty());
  EXPECT_EQ(diagnostics["params"]["diagnostics"][0]["range"]["start"]["line"], 1);  // 0-based
}

TEST(StudioServer, TheDebuggerAttachesToTheStudiosDrive) {
  Server server;
  Client c(server.port(), "/ws/dap");
  c.send(
      json({{"seq", 1}, {"type", "request"}, {"command", "initialize"}, {"arguments", {}}}).dump());
  const json init = c.read();
  EXPECT_EQ(init["success"], true);
  EXPECT_EQ(init["body"]["supportsConditionalBreakpoints"], true);
  c.send(json({{"seq", 2}, {"type", "request"}, {"command", "attach"}, {"arguments", {}}}).dump());
  EXPECT_EQ(c.read()["success"], true);
  EXPECT_EQ(c.read_type("initialized")["type"], "event");
  c.send("not json either");
  EXPECT_EQ(c.read_type("output")["body"]["category"], "stderr");
  // A second debugging page takes over; the first is closed.
  Client d(server.port(), "/ws/dap");
  while (!c.read().is_null()) {
  }
  d.send(
      json({{"seq", 1}, {"type", "request"}, {"command", "initialize"}, {"arguments", {}}}).dump());
  EXPECT_EQ(d.read()["success"], true);
}

// A binary frame where the drive takes JSON texts is answered like any malformed message.
TEST(StudioServer, ABinaryFrameOnTheDriveSocketIsAnswered) {
  Server server;
  Client c(server.port(), "/ws/drive");
  c.read();
  c.ws.binary(true);
  c.send(std::string("\x00\x01\xff{", 4));
  EXPECT_EQ(c.read_type("error")["message"], "not a JSON object");
  c.ws.text(true);
  c.send(json({{"op", "line"}, {"text", "2+3"}}).dump());
  EXPECT_EQ(c.read_type("answers")["answers"][0]["text"], "5");
}

// JSON-RPC 2.0 section 5: a text that does not parse gets a parse error (-32700, id null); the
// language server goes on and answers the next request.
TEST(StudioServer, TheLanguageServerAnswersAMalformedMessageAndGoesOn) {
  Server server;
  Client c(server.port(), "/ws/lsp");
  c.send("{ not json");
  const json error = c.read();
  EXPECT_EQ(error["error"]["code"], -32700) << error.dump();
  EXPECT_TRUE(error["id"].is_null());
  c.send(json({{"jsonrpc", "2.0"},
               {"id", 1},
               {"method", "initialize"},
               {"params", {{"capabilities", json::object()}}}})
             .dump());
  EXPECT_EQ(c.read()["id"], 1);
}

// Over the socket as in StudioDrive.APageGoneMidDownloadLeavesTheStoredProgram: a page that
// sends all DL lines of another program but the last and vanishes (no close frame) takes its
// download with it; the next page's DL##END has none to end (210), and the program stored before
// runs and answers its query as the dialect says.
TEST(StudioServer, APageGoneMidProgramDownloadLeavesTheStoredProgram) {
  Server server;
  const dialect::Dialect& gold = *dialects::find("gold");
  const dialect::SampleProgram& sample = gold.sample_program();
  Client a(server.port(), "/ws/drive");
  a.read();
  a.send(json({{"op", "build"}, {"source", sample.source}}).dump());
  ASSERT_EQ(a.read_type("build")["ok"], true);
  const auto other = gold.compile_source(
      {"other.ehl",
       *read_text_file(std::string(UPROG_SOURCE_DIR) + "/examples/gold/first_move.ehl")},
      {});
  const auto lines = gold.download_lines(other.stored_form);
  ASSERT_GT(lines.size(), 2u);
  {
    Client b(server.port(), "/ws/drive");
    b.read();
    for (size_t i = 0; i + 1 < lines.size(); ++i) {
      b.send(json({{"op", "line"}, {"text", lines[i]}}).dump());
    }
    ASSERT_TRUE(b.read_type("answers").is_object());  // the server has read them
    beast::get_lowest_layer(b.ws).socket().close();   // gone, mid-download
  }
  Client c(server.port(), "/ws/drive");
  c.read();
  c.send(json({{"op", "line"}, {"text", "DL##END"}}).dump());
  EXPECT_EQ(c.read_type("answers")["answers"][0]["error"], dialect::kDlNoDownload);
  c.send(json({{"op", "speed"}, {"factor", 10}}).dump());
  c.send(json({{"op", "start"}}).dump());
  EXPECT_EQ(c.read_type("started")["ok"], true);
  std::string answer;
  for (int i = 0; i < 40 && answer != sample.answer; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    c.send(json({{"op", "line"}, {"text", sample.query}}).dump());
    answer = c.read_type("answers")["answers"][0]["text"];
  }
  EXPECT_EQ(answer, sample.answer);
}

// A page that reads, but slower than "as fast as possible" makes samples (8 channels, 20 ms a
// message), is waited for (StudioApp::kBehindBytes) rather than dropped at the unread limit: its
// stream never ends, and the drive's time goes on.
TEST(StudioServer, AsFastAsPossibleWaitsForASlowPage) {
  Server server;
  Client c(server.port(), "/ws/drive");
  c.send(json({{"op", "scope"},
               {"channels", {"PX", "VX", "PE", "IQ", "MS", "DV[1]", "DV[2]", "DV[3]"}}})
             .dump());
  c.send(json({{"op", "speed"}, {"factor", "max"}}).dump());
  const uint64_t before = server.now_us();
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  beast::flat_buffer buffer;
  while (std::chrono::steady_clock::now() < end && !c.error) {
    buffer.clear();
    c.ws.read(buffer, c.error);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  EXPECT_EQ(c.error, beast::error_code{}) << c.error.message();
  EXPECT_GT(server.now_us(), before + 1'000'000);  // at least the wall clock's pace
}

}  // namespace
}  // namespace uprog::studio
