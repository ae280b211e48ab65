#include "tools/view/web_server.hpp"

#include <civetweb.h>

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "tools/view/web_assets.hpp"

namespace ifar::view {
namespace {

WebServerSettings loopbackSettings()
{
  WebServerSettings settings;
  settings.address = "127.0.0.1";
  settings.port = 0;
  settings.assets = {{"/index.html", "text/html; charset=utf-8", "<html>ifar</html>"},
                     {"/view.js", "text/javascript; charset=utf-8", "let a = 1;"}};
  return settings;
}

struct HttpAnswer {
  int status = 0;
  std::string content_type;
  std::string body;
};

HttpAnswer get(int port, const std::string& path)
{
  char error[256] = {0};
  const std::string request = "GET " + path + " HTTP/1.0\r\nHost: 127.0.0.1\r\n\r\n";
  mg_connection* connection = mg_download("127.0.0.1", port, 0, error, sizeof error, "%s", request.c_str());
  HttpAnswer answer;
  if (connection == nullptr) {
    ADD_FAILURE() << "GET " << path << ": " << error;
    return answer;
  }
  const mg_response_info* response = mg_get_response_info(connection);
  answer.status = response->status_code;
  for (int index = 0; index < response->num_headers; ++index) {
    if (std::string(response->http_headers[index].name) == "Content-Type") {
      answer.content_type = response->http_headers[index].value;
    }
  }
  char buffer[4096];
  int read = 0;
  while ((read = mg_read(connection, buffer, sizeof buffer)) > 0) {
    answer.body.append(buffer, static_cast<std::size_t>(read));
  }
  mg_close_connection(connection);
  return answer;
}

/// What a WebSocket client got, filled from civetweb's client thread.
struct Received {
  std::mutex mutex;
  std::condition_variable changed;
  std::vector<std::string> frames;
  std::vector<int> opcodes;
  bool closed = false;

  bool waitFor(std::size_t count)
  {
    std::unique_lock<std::mutex> lock(mutex);
    return changed.wait_for(lock, std::chrono::seconds(5), [&] { return frames.size() >= count; });
  }
};

int clientData(mg_connection* /*connection*/, int bits, char* data, std::size_t length, void* user)
{
  auto& received = *static_cast<Received*>(user);
  const std::lock_guard<std::mutex> lock(received.mutex);
  received.frames.emplace_back(data, length);
  received.opcodes.push_back(bits & 0x0F);
  received.changed.notify_all();
  return 1;
}

void clientClosed(const mg_connection* /*connection*/, void* user)
{
  auto& received = *static_cast<Received*>(user);
  const std::lock_guard<std::mutex> lock(received.mutex);
  received.closed = true;
  received.changed.notify_all();
}

std::vector<ClientEvent> waitForEvents(WebServer& server, std::size_t count)
{
  std::vector<ClientEvent> events;
  for (int attempt = 0; attempt < 500 && events.size() < count; ++attempt) {
    for (ClientEvent& event : server.takeEvents()) {
      events.push_back(std::move(event));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return events;
}

// One server for the tests that connect to it: civetweb takes 2 s to stop once it has served a connection.
class WebServerTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { shared_server = new WebServer(loopbackSettings()); }
  static void TearDownTestSuite()
  {
    delete shared_server;
    shared_server = nullptr;
  }
  static WebServer* shared_server;
  WebServer& server = *shared_server;
};
WebServer* WebServerTest::shared_server = nullptr;

TEST_F(WebServerTest, ServesItsFilesAndIndexAtTheRoot)
{
  ASSERT_GT(server.port(), 0);
  const HttpAnswer root = get(server.port(), "/");
  EXPECT_EQ(root.status, 200);
  EXPECT_EQ(root.body, "<html>ifar</html>");
  EXPECT_EQ(root.content_type, "text/html; charset=utf-8");
  const HttpAnswer script = get(server.port(), "/view.js");
  EXPECT_EQ(script.body, "let a = 1;");
  EXPECT_EQ(script.content_type, "text/javascript; charset=utf-8");
  const HttpAnswer missing = get(server.port(), "/nothing.js");
  EXPECT_EQ(missing.status, 404);
  EXPECT_EQ(missing.body, "not found: /nothing.js\n");
}

TEST_F(WebServerTest, ASocketJoinsReceivesInOrderSpeaksAndLeaves)
{
  Received received;
  char error[256] = {0};
  mg_connection* client = mg_connect_websocket_client("127.0.0.1", server.port(), 0, error, sizeof error,
                                                      "/ws", nullptr, &clientData, &clientClosed, &received);
  ASSERT_NE(client, nullptr) << error;
  std::vector<ClientEvent> events = waitForEvents(server, 1);
  ASSERT_EQ(events.size(), 1U);
  EXPECT_EQ(events[0].kind, ClientEvent::Kind::kJoined);
  EXPECT_EQ(events[0].text, "127.0.0.1");
  EXPECT_EQ(events[0].endpoint, "/ws");
  EXPECT_EQ(server.clientCount(), 1U);
  const ClientId id = events[0].client;
  server.send(id, {{false, "first"}, {false, "second"}, {true, std::string("\x01\x00\x02", 3)}});
  ASSERT_TRUE(received.waitFor(3));
  {
    const std::lock_guard<std::mutex> lock(received.mutex);
    EXPECT_EQ(received.frames[0], "first");
    EXPECT_EQ(received.frames[1], "second");
    EXPECT_EQ(received.frames[2], std::string("\x01\x00\x02", 3));
    EXPECT_EQ(received.opcodes[0], MG_WEBSOCKET_OPCODE_TEXT);
    EXPECT_EQ(received.opcodes[2], MG_WEBSOCKET_OPCODE_BINARY);
  }
  const std::string hello = "{\"op\":\"hello\"}";
  mg_websocket_client_write(client, MG_WEBSOCKET_OPCODE_TEXT, hello.data(), hello.size());
  events = waitForEvents(server, 1);
  ASSERT_EQ(events.size(), 1U);
  EXPECT_EQ(events[0].kind, ClientEvent::Kind::kText);
  EXPECT_EQ(events[0].text, hello);
  EXPECT_EQ(events[0].endpoint, "/ws");
  const std::string bytes("\x01\x00\x07", 3);
  mg_websocket_client_write(client, MG_WEBSOCKET_OPCODE_BINARY, bytes.data(), bytes.size());
  events = waitForEvents(server, 1);
  ASSERT_EQ(events.size(), 1U);
  EXPECT_EQ(events[0].kind, ClientEvent::Kind::kBinary);
  EXPECT_EQ(events[0].text, bytes);
  mg_close_connection(client);
  events = waitForEvents(server, 1);
  ASSERT_EQ(events.size(), 1U);
  EXPECT_EQ(events[0].kind, ClientEvent::Kind::kLeft);
  EXPECT_EQ(events[0].client, id);
  EXPECT_EQ(events[0].endpoint, "/ws");
  EXPECT_EQ(server.clientCount(), 0U);
  server.send(id, {{false, "to nobody"}});  // a client that left is not an error
}

TEST(WebServer, ASocketWithASubprotocolRefusesAClientThatDoesNotAskForIt)
{
  WebServerSettings settings = loopbackSettings();
  settings.sockets = {{"/ws", ""}, {"/foxglove", "foxglove.websocket.v1"}};
  WebServer server(settings);
  // civetweb's client offers no subprotocol: welcome on /ws, refused on /foxglove (tests/integration/view
  // connects there with one).
  Received received;
  char error[256] = {0};
  mg_connection* refused =
      mg_connect_websocket_client("127.0.0.1", server.port(), 0, error, sizeof error, "/foxglove", nullptr,
                                  &clientData, &clientClosed, &received);
  EXPECT_EQ(refused, nullptr);
  if (refused != nullptr) {
    mg_close_connection(refused);
  }
  mg_connection* page = mg_connect_websocket_client("127.0.0.1", server.port(), 0, error, sizeof error, "/ws",
                                                    nullptr, &clientData, &clientClosed, &received);
  ASSERT_NE(page, nullptr) << error;
  const std::vector<ClientEvent> events = waitForEvents(server, 1);
  ASSERT_EQ(events.size(), 1U);
  EXPECT_EQ(events[0].endpoint, "/ws");
  mg_close_connection(page);
  waitForEvents(server, 1);
}

TEST(WebServer, APortInUseIsRefusedNamingIt)
{
  WebServer first(loopbackSettings());
  WebServerSettings settings = loopbackSettings();
  settings.port = first.port();
  try {
    const WebServer second(settings);
    FAIL() << "a second server listened on the same port";
  } catch (const std::runtime_error& error) {
    EXPECT_EQ(std::string(error.what()), "cannot listen on 127.0.0.1:" + std::to_string(first.port()) +
                                             " (address in use, or not this host's)");
  }
}

TEST(WebAssets, ThePageHasEveryFileItsIndexNames)
{
  const std::vector<WebAsset> assets = webAssets();
  const WebAsset* index = nullptr;
  for (const WebAsset& asset : assets) {
    if (asset.path == "/index.html") {
      index = &asset;
    }
  }
  ASSERT_NE(index, nullptr);
  const std::string html(index->content);
  std::vector<std::string> named;
  for (const std::string attribute : {"src=\"", "href=\""}) {
    for (std::size_t at = html.find(attribute); at != std::string::npos; at = html.find(attribute, at + 1)) {
      const std::size_t start = at + attribute.size();
      named.push_back("/" + html.substr(start, html.find('"', start) - start));
    }
  }
  EXPECT_EQ(named.size(), 4U);  // view.css, draw.js, panels.js, view.js
  for (const std::string& path : named) {
    bool found = false;
    for (const WebAsset& asset : assets) {
      found = found || asset.path == path;
    }
    EXPECT_TRUE(found) << "index.html names " << path << ", which is not built in";
  }
}

}  // namespace
}  // namespace ifar::view
