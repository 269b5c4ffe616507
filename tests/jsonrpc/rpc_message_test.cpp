// JSON-RPC 2.0 envelopes (jsonrpc.org/specification, sections 4, 5 and 5.1) and DAP's
// (the Debug Adapter Protocol's ProtocolMessage and Request): what is a request, a notification,
// an answerable error, and what is dropped.
#include "jsonrpc/rpc_message.h"

#include <gtest/gtest.h>

#include "jsonrpc/dap_envelope.h"
#include "jsonrpc/framing.h"

namespace uprog::jsonrpc {
namespace {

using Kind = RpcMessage::Kind;

TEST(RpcMessage, RequestsAndNotifications) {
  RpcMessage m = parse_rpc_message(R"({"jsonrpc":"2.0","id":1,"method":"initialize",
                                       "params":{}})");
  EXPECT_EQ(m.kind, Kind::Request);
  EXPECT_EQ(m.id, json(1));
  EXPECT_EQ(m.method, "initialize");
  m = parse_rpc_message(R"({"jsonrpc":"2.0","id":"a","method":"shutdown"})");
  EXPECT_EQ(m.kind, Kind::Request);
  EXPECT_EQ(m.id, json("a"));
  EXPECT_TRUE(m.params.is_null());
  m = parse_rpc_message(R"({"jsonrpc":"2.0","method":"initialized","params":{}})");
  EXPECT_EQ(m.kind, Kind::Notification);
  m = parse_rpc_message(R"({"jsonrpc":"2.0","id":4,"result":null})");
  EXPECT_EQ(m.kind, Kind::Response);
}

TEST(RpcMessage, SpecificationErrorCodes) {
  // 5.1: -32700 for a text that is not JSON, with a null id.
  RpcMessage m = parse_rpc_message("{\"jsonrpc\": \"2.0\", \"method\": \"foobar, \"params\": ");
  EXPECT_EQ(m.kind, Kind::Invalid);
  EXPECT_EQ(static_cast<int>(m.code), -32700);
  EXPECT_TRUE(m.id.is_null());
  // -32600: not a request object; with a usable id, the answer goes to it.
  m = parse_rpc_message(R"({"jsonrpc": "2.0", "method": 1, "params": "bar", "id": 7})");
  EXPECT_EQ(m.kind, Kind::Invalid);
  EXPECT_EQ(static_cast<int>(m.code), -32600);
  EXPECT_EQ(m.id, json(7));
  m = parse_rpc_message("[1,2,3]");
  EXPECT_EQ(m.kind, Kind::Invalid);
  EXPECT_EQ(static_cast<int>(m.code), -32600);
  m = parse_rpc_message(R"({"jsonrpc":"1.0","id":3,"method":"x"})");
  EXPECT_EQ(m.kind, Kind::Invalid);
  EXPECT_EQ(m.id, json(3));
  m = parse_rpc_message(R"({"jsonrpc":"2.0","id":3,"method":"x","params":5})");
  EXPECT_EQ(m.kind, Kind::Invalid);
  m = parse_rpc_message(R"({"jsonrpc":"2.0","id":{"a":1},"method":"x"})");
  EXPECT_EQ(m.kind, Kind::Invalid);
  EXPECT_TRUE(m.id.is_null());
}

TEST(RpcMessage, NestingDeeperThanAnyMessageIsRefusedBeforeItIsBuilt) {
  // 65 levels: one past kMaxNesting; inside a string brackets do not count.
  const std::string deep = R"({"jsonrpc":"2.0","id":1,"method":"x","params":)" +
                           std::string(64, '[') + std::string(64, ']') + "}";
  RpcMessage m = parse_rpc_message(deep);
  EXPECT_EQ(m.kind, Kind::Invalid);
  EXPECT_EQ(static_cast<int>(m.code), -32700);
  const std::string shallow =
      R"({"jsonrpc":"2.0","id":1,"method":"x","params":{"s":")" + std::string(100, '[') + R"("}})";
  EXPECT_EQ(parse_rpc_message(shallow).kind, Kind::Request);
  EXPECT_EQ(check_dap_message(R"({"seq":1,"type":"request","command":"x","arguments":{"a":)" +
                              std::string(70, '[') + std::string(70, ']') + "}}")
                .kind,
            DapEnvelope::Kind::NotRequest);
}

TEST(RpcMessage, AWrongNotificationIsDropped) {
  EXPECT_EQ(parse_rpc_message(R"({"jsonrpc":"2.0","method":5})").kind, Kind::Dropped);
  EXPECT_EQ(parse_rpc_message(R"({"jsonrpc":"2.0","method":"x","params":"s"})").kind,
            Kind::Dropped);
  EXPECT_EQ(parse_rpc_message(R"({"jsonrpc":"2.0"})").kind, Kind::Dropped);
}

TEST(RpcMessage, TheTextsSent) {
  EXPECT_EQ(json::parse(rpc_error(json(2), ErrorCode::MethodNotFound, "no")),
            json::parse(R"({"jsonrpc":"2.0","id":2,"error":{"code":-32601,"message":"no"}})"));
  EXPECT_EQ(json::parse(rpc_result(json("x"), nullptr)),
            json::parse(R"({"jsonrpc":"2.0","id":"x","result":null})"));
  EXPECT_EQ(json::parse(rpc_notification("exit", nullptr)),
            json::parse(R"({"jsonrpc":"2.0","method":"exit","params":null})"));
}

TEST(DapEnvelope, TheProbesMessages) {
  // The two messages that aborted `uprog dap` (issue 45): a string seq is a request with a wrong
  // field, answered; a numeric type names no request, dropped.
  DapEnvelope e = check_dap_message(R"({"seq":"x","type":"request","command":"initialize"})");
  EXPECT_EQ(e.kind, DapEnvelope::Kind::BadRequest);
  EXPECT_EQ(e.command, "initialize");
  EXPECT_EQ(e.seq, 0);
  e = check_dap_message(R"({"seq":1,"type":5,"command":"initialize"})");
  EXPECT_EQ(e.kind, DapEnvelope::Kind::NotRequest);
  e = check_dap_message(R"({"seq":3,"type":"request","command":7})");
  EXPECT_EQ(e.kind, DapEnvelope::Kind::BadRequest);
  EXPECT_EQ(e.seq, 3);
  e = check_dap_message(R"({"seq":3,"type":"request","command":"next","arguments":[]})");
  EXPECT_EQ(e.kind, DapEnvelope::Kind::BadRequest);
  e = check_dap_message(R"({"seq":3,"type":"request","command":"threads"})");
  EXPECT_EQ(e.kind, DapEnvelope::Kind::Request);
  EXPECT_TRUE(e.message["arguments"].is_object());  // absent arguments read as {}
  EXPECT_EQ(check_dap_message("nonsense").kind, DapEnvelope::Kind::NotRequest);
  EXPECT_EQ(check_dap_message("[]").kind, DapEnvelope::Kind::NotRequest);
}

TEST(Framing, MessagesInPiecesAndBadHeaders) {
  MessageReader r;
  const std::string framed = frame_message(R"({"a":1})") + frame_message("{}");
  for (char ch : framed) r.feed(std::string_view(&ch, 1));
  EXPECT_EQ(r.next(), std::optional<std::string>(R"({"a":1})"));
  EXPECT_EQ(r.next(), std::optional<std::string>("{}"));
  EXPECT_EQ(r.next(), std::nullopt);
  // A bad header is dropped and the stream goes on with the next message.
  MessageReader bad;
  bad.feed("Content-Type: x\r\n\r\n" + frame_message("{}"));
  EXPECT_EQ(bad.next(), std::optional<std::string>("{}"));
  std::vector<std::string> problems = bad.take_problems();
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("without Content-Length"), std::string::npos);
  EXPECT_TRUE(bad.take_problems().empty());
  MessageReader huge;
  huge.feed("Content-Length: 99999999999\r\n\r\nContent-Length: x\r\n\r\n" + frame_message("[1]"));
  EXPECT_EQ(huge.next(), std::optional<std::string>("[1]"));
  EXPECT_EQ(huge.take_problems().size(), 2u);
  MessageReader endless;  // no header end in 4096 bytes: dropped, and a message after it read
  endless.feed(std::string(5000, 'x'));
  EXPECT_EQ(endless.next(), std::nullopt);
  EXPECT_EQ(endless.take_problems().size(), 1u);
  endless.feed(frame_message("{}"));
  EXPECT_EQ(endless.next(), std::optional<std::string>("{}"));
  MessageReader typed;  // LSP's optional Content-Type field is read past
  typed.feed(
      "Content-Length: 2\r\nContent-Type: application/vscode-jsonrpc; charset=utf-8"
      "\r\n\r\n{}");
  EXPECT_EQ(typed.next(), std::optional<std::string>("{}"));
}

}  // namespace
}  // namespace uprog::jsonrpc
