#include "src/studio/server.h"

#include <atomic>
#include <filesystem>
#include <functional>
#include <mutex>

#include <httplib.h>

#include "src/output.h"
#include "src/studio/animation.h"
#include "src/studio/api.h"
#include "src/studio/page.h"
#include "src/studio/renders.h"

namespace sandpic::studio {

namespace {

// A reply for any request: a user's mistake is a 400 naming the key, our own
// failure a 500; nothing escapes into httplib's threads.
Reply guarded(const std::function<Reply()>& f) {
  try {
    return f();
  } catch (const Busy& e) {
    return error_reply(e.what(), 409);
  } catch (const TooLarge& e) {
    return error_reply(e.what(), 413);
  } catch (const InputError& e) {
    return error_reply(e.what());
  } catch (const nlohmann::json::exception& e) {  // a value no key check caught
    return error_reply(std::string("bad value: ") + e.what());
  } catch (const std::bad_alloc&) {
    return error_reply("not enough memory for this scene; lower window or region sizes");
  } catch (const std::exception& e) {
    return error_reply(e.what(), 500);
  }
}

void send(httplib::Response& res, const Reply& r) {
  res.status = r.status;
  for (const auto& [k, v] : r.headers) res.set_header(k, v);
  res.set_content(r.body, r.content_type);
}

// A preview queue of one: the preview running and the newest waiting; an
// older waiting one is answered 409 (the page has moved on) without running.
class LatestOnly {
 public:
  Reply run(const std::function<Reply()>& f) {
    const uint64_t ticket = ++latest_;
    std::lock_guard lock(running_);
    if (ticket != latest_) return error_reply("superseded by a newer preview", 409);
    return f();
  }

 private:
  std::mutex running_;
  std::atomic<uint64_t> latest_{0};
};

std::string under_root(const std::string& root, const std::string& path) {
  return std::filesystem::path(path).is_absolute() ? path : (std::filesystem::path(root) / path).string();
}

}  // namespace

struct Server::Impl {
  ServerOptions opt;
  Scene start;
  Renders renders;
  LatestOnly previews;
  LatestOnly animations;  // apart: playing the fall must not supersede the preview
  httplib::Server http;
  int port = 0;

  explicit Impl(const ServerOptions& o)
      : opt(o),
        start(o.scene_path.empty() ? Scene{} : load_scene(o.scene_path)),
        renders(under_root(o.root, o.renders)) {
    validate(start);
    routes();
  }

  void routes() {
    // The largest body any route takes (a picture); each route checks its own.
    http.set_payload_max_length(kMaxImageBytes);
    http.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
      const std::string why = refusal(opt.host, req.method, req.get_header_value("Host"), req.get_header_value("Origin"));
      if (why.empty()) return httplib::Server::HandlerResponse::Unhandled;
      send(res, error_reply(why, 403));
      return httplib::Server::HandlerResponse::Handled;
    });
    http.Get("/", [](const httplib::Request&, httplib::Response& res) { page(res, "index.html"); });
    http.Get(R"(/([a-z0-9-]+\.(?:html|js|css)))", [](const httplib::Request& req, httplib::Response& res) {
      page(res, req.matches[1].str());
    });
    http.Get("/api/scene", [this](const httplib::Request&, httplib::Response& res) { send(res, scene_reply(start)); });
    // Every scene key with its kind, range, choices and help: the page builds its controls from it.
    http.Get("/api/keys", [](const httplib::Request&, httplib::Response& res) { send(res, json_reply(keys_json())); });
    http.Post("/api/preview", [this](const httplib::Request& req, httplib::Response& res) {
      send(res, previews.run([&] { return guarded([&] { return preview(req.body, opt.root, scale_param(req.get_param_value("scale"))); }); }));
    });
    http.Post("/api/animation", [this](const httplib::Request& req, httplib::Response& res) {
      send(res, animations.run([&] {
             return guarded([&] {
               const AnimationRequest a = animation_request(req.get_param_value("frames"), req.get_param_value("scale"),
                                                            req.get_param_value("fps"), req.get_param_value("format"));
               return animation(req.body, opt.root, a);
             });
           }));
    });
    http.Post("/api/image", [this](const httplib::Request& req, httplib::Response& res) {
      send(res, guarded([&] { return upload_image(req.body, opt.root); }));
    });
    http.Post("/api/units", [this](const httplib::Request& req, httplib::Response& res) {
      send(res, guarded([&] { return units(req.body, opt.root); }));
    });
    http.Post("/api/render", [this](const httplib::Request& req, httplib::Response& res) {
      send(res, guarded([&] {
             const Scene s = scaled(scene_from_request(req.body, opt.root), scale_param(req.get_param_value("scale")));
             return json_reply({{"id", renders.start(s)}});
           }));
    });
    http.Post("/api/scene", [this](const httplib::Request& req, httplib::Response& res) {
      send(res, guarded([&] { return complete_scene(req.body, opt.root); }));
    });
    http.Get(R"(/api/render/(\d{1,9}))", [this](const httplib::Request& req, httplib::Response& res) {
      auto job = renders.job(std::stoi(req.matches[1].str()));
      send(res, job ? json_reply(status_json(*job)) : error_reply("no such render", 404));
    });
    http.Post(R"(/api/render/(\d{1,9})/cancel)", [this](const httplib::Request& req, httplib::Response& res) {
      const int id = std::stoi(req.matches[1].str());
      if (!renders.job(id)) return send(res, error_reply("no such render", 404));
      if (!renders.cancel(id)) return send(res, error_reply("render " + std::to_string(id) + " is done already", 409));
      send(res, json_reply({{"id", id}, {"cancelling", true}}));
    });
    http.Get(R"(/api/render/(\d{1,9})/picture\.png)", [this](const httplib::Request& req, httplib::Response& res) {
      picture(res, std::stoi(req.matches[1].str()));
    });
  }

  static void page(httplib::Response& res, const std::string& name) {
    const PageFile* f = page_file(name);
    if (!f) return send(res, error_reply("no such page file", 404));
    res.set_content(std::string(f->body), std::string(content_type(name)));
  }

  void picture(httplib::Response& res, int id) {
    auto job = renders.job(id);
    if (!job || !job->done || job->picture.empty()) return send(res, error_reply("no finished picture", 404));
    auto bytes = read_text(job->picture);
    if (!bytes) return send(res, error_reply("the picture file is gone: " + job->picture, 410));
    res.set_content(*bytes, "image/png");
  }
};

Server::Server(const ServerOptions& opt) : impl_(std::make_unique<Impl>(opt)) {}
Server::~Server() = default;

int Server::bind() {
  Impl& i = *impl_;
  i.port = i.opt.port == 0 ? i.http.bind_to_any_port(i.opt.host) : (i.http.bind_to_port(i.opt.host, i.opt.port) ? i.opt.port : -1);
  if (i.port < 0)
    throw InputError("--host/--port: cannot listen on " + i.opt.host + ":" + std::to_string(i.opt.port));
  return i.port;
}

void Server::run() { impl_->http.listen_after_bind(); }
void Server::stop() { impl_->http.stop(); }

std::string_view content_type(std::string_view name) {
  if (name.ends_with(".html")) return "text/html; charset=utf-8";
  if (name.ends_with(".js")) return "text/javascript; charset=utf-8";
  if (name.ends_with(".css")) return "text/css; charset=utf-8";
  return "application/octet-stream";
}

}  // namespace sandpic::studio
