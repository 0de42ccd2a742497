#include "apps/studio/server.h"

#include <httplib.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdio>
#include <deque>
#include <fstream>
#include <mutex>
#include <random>
#include <regex>
#include <sstream>
#include <thread>
#include <utility>

#include <nlohmann/json.hpp>

#include "apps/studio/jobs.h"
#include "apps/studio/reference.h"
#include "apps/studio/workspace.h"

namespace insula::studio {
namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

constexpr std::size_t kMaxBody = std::size_t{16} << 20;  // an edited file or a lot file
constexpr std::size_t kModelsKept = 8;                   // builds whose files a page may fetch
// What `insula build` and `insula mass` write (docs/formats.md).
constexpr std::array<std::string_view, 7> kExportFormats = {
    "glb", "gltf", "obj", "city.json", "city.jsonl", "svg", "png"};

// The name before its first dot ("district" of district.cga, "city" of city.graph.json).
std::string stem_of(const fs::path& path) {
  const std::string name = path.filename().string();
  return name.substr(0, name.find('.'));
}

// Footprints (GeoJSON, OpenStreetMap): the studio shows their mass model (`insula mass`).
bool is_footprint_file(const fs::path& path) {
  const std::string name = path.filename().string();
  return name.ends_with(".geojson") || name.ends_with(".osm") || name.ends_with(".osm.pbf");
}

std::string random_token() {
  std::random_device random;
  std::string token;
  static constexpr char kDigits[] = "0123456789abcdef";
  for (int i = 0; i < 32; ++i) token += kDigits[random() % 16];
  return token;
}

// cpp-httplib compresses text, JSON and JavaScript with brotli at its highest quality when the
// browser accepts it: seconds for a city's GeoJSON or the page's script on this machine. The
// studio serves over the loopback, so its answers carry types the library leaves alone (a
// parameter after the type, or bytes for file text).
constexpr const char* kJson = "application/json; charset=utf-8";
constexpr const char* kFileText = "application/octet-stream";

void reply_json(httplib::Response& response, const Json& body, int status = 200) {
  response.status = status;
  response.set_content(body.dump(), kJson);
}

void refuse(httplib::Response& response, int status, const std::string& why) {
  reply_json(response, {{"error", why}}, status);
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The file's text as edited, written beside it (so its imports, assets and lots resolve as they
// would for the file itself) under a hidden name; removed when the job is done.
class Draft {
 public:
  Draft(const fs::path& file, const std::string& text) {
    std::random_device random;
    const std::string name = file.filename().string();
    // Keep the whole extension (".graph.json"): the command line picks the front-end by it.
    const std::size_t dot = name.find('.');
    const std::string stem = dot == std::string::npos ? name : name.substr(0, dot);
    const std::string ext = dot == std::string::npos ? "" : name.substr(dot);
    path_ = file.parent_path() / (".studio-" + std::to_string(random()) + "-" + stem + ext);
    error_ = Workspace::save(path_, text);
  }
  ~Draft() {
    std::error_code ignored;
    fs::remove(path_, ignored);
  }
  Draft(const Draft&) = delete;
  Draft& operator=(const Draft&) = delete;
  const fs::path& path() const { return path_; }
  const std::string& error() const { return error_; }

 private:
  fs::path path_;
  std::string error_;
};

// The command line's output with the draft's name given back as the file's own.
std::string as_shown(std::string output, const std::string& draft, const std::string& shown) {
  for (std::size_t at = output.find(draft); at != std::string::npos;
       at = output.find(draft, at + shown.size())) {
    output.replace(at, draft.size(), shown);
  }
  return output;
}

// `file:line:col: error[CODE]: message` lines of the command line's output as records.
Json diagnostics_of(const std::string& output) {
  static const std::regex kLine(R"(^(.*?):(\d+):(\d+): (error|warning)\[([A-Z0-9]+)\]: (.*)$)");
  Json out = Json::array();
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (!std::regex_match(line, m, kLine)) continue;
    out.push_back({{"file", m[1].str()},
                   {"line", std::stoi(m[2].str())},
                   {"column", std::stoi(m[3].str())},
                   {"severity", m[4].str()},
                   {"code", m[5].str()},
                   {"message", m[6].str()}});
  }
  return out;
}

class Studio {
 public:
  Studio(const StudioOptions& options, Workspace workspace)
      : options_(options), workspace_(std::move(workspace)), jobs_(options.executable, {}) {}

  void routes(httplib::Server& server) {
    server.set_payload_max_length(kMaxBody);
    server.set_pre_routing_handler([this](const httplib::Request& request,
                                          httplib::Response& response) {
      if (request.get_param_value("token") == options_.token) {
        // The page's own files (its script, its style) then come with the cookie.
        response.set_header(
            "Set-Cookie", "insula_token=" + options_.token + "; HttpOnly; SameSite=Strict; Path=/");
        return httplib::Server::HandlerResponse::Unhandled;
      }
      if (authorized(request)) return httplib::Server::HandlerResponse::Unhandled;
      refuse(response, 403, "a request without the studio's token");
      return httplib::Server::HandlerResponse::Handled;
    });
    server.Get("/api/files", [this](const httplib::Request&, httplib::Response& response) {
      Json files = Json::array();
      for (const Workspace::Entry& e : workspace_.files()) {
        files.push_back({{"path", e.path}, {"bytes", e.bytes}});
      }
      reply_json(response, {{"folder", workspace_.root().filename().string()}, {"files", files}});
    });
    server.Post("/api/random",
                [this](const httplib::Request& request, httplib::Response& response) {
                  random_building(request, response);
                });
    server.Get("/api/reference", [](const httplib::Request&, httplib::Response& response) {
      static const std::string reference = reference_json().dump();
      response.set_content(reference, kJson);
    });
    server.Get("/api/file", [this](const httplib::Request& request, httplib::Response& response) {
      const std::optional<fs::path> path = file_of(request, response);
      if (!path) return;
      if (!fs::is_regular_file(*path)) return refuse(response, 404, "no such file");
      response.set_content(read_text(*path), kFileText);
    });
    server.Put("/api/file", [this](const httplib::Request& request, httplib::Response& response) {
      const std::optional<fs::path> path = file_of(request, response);
      if (!path) return;
      if (!is_studio_file(*path)) return refuse(response, 400, "not a file the studio edits");
      if (const std::string error = Workspace::save(*path, request.body); !error.empty()) {
        return refuse(response, 500, error);
      }
      reply_json(response, {{"saved", request.get_param_value("path")}});
    });
    server.Post("/api/check", [this](const httplib::Request& request, httplib::Response& response) {
      run_job(request, response, Job::kCheck);
    });
    server.Post("/api/build", [this](const httplib::Request& request, httplib::Response& response) {
      run_job(request, response, Job::kBuild);
    });
    server.Post("/api/export",
                [this](const httplib::Request& request, httplib::Response& response) {
                  run_job(request, response, Job::kExport);
                });
    server.Get(R"(/api/model/(\d+)\.(glb|svg))",
               [this](const httplib::Request& request, httplib::Response& response) {
                 const bool glb = request.matches[2].str() == "glb";
                 const std::string bytes = built_file(std::stoull(request.matches[1].str()), glb);
                 if (bytes.empty()) {
                   return refuse(response, 404, "no such build (built again since?)");
                 }
                 response.set_content(bytes, glb ? "model/gltf-binary" : "image/svg+xml");
               });
    server.set_file_extension_and_mimetype_mapping("js", "application/javascript; charset=utf-8");
    server.set_file_extension_and_mimetype_mapping("map", kJson);
    if (!options_.web.empty() && fs::is_directory(options_.web)) {
      server.set_mount_point("/", options_.web.string());
    }
  }

 private:
  // The token as a header (the page's API calls) or as the cookie set with the page.
  bool authorized(const httplib::Request& request) const {
    if (request.get_header_value("X-Insula-Token") == options_.token) return true;
    const std::string cookies = "; " + request.get_header_value("Cookie");
    return cookies.find("; insula_token=" + options_.token) != std::string::npos;
  }

  std::optional<fs::path> file_of(const httplib::Request& request, httplib::Response& response) {
    std::string why;
    std::optional<fs::path> path = workspace_.resolve(request.get_param_value("path"), why);
    if (!path) refuse(response, 403, "refused: " + why);
    return path;
  }

  enum class Job { kCheck, kBuild, kExport };

  // Checks (`insula check`), builds (`insula build -o model.glb --report`; footprints: `insula
  // mass`) or exports (the same build into the folder's `exports/`) the request's body as the text
  // of `path`, with `lot` (a file of the folder) and `seed` for builds.
  void run_job(const httplib::Request& request, httplib::Response& response, Job kind) {
    const std::optional<fs::path> path = file_of(request, response);
    if (!path) return;
    const std::string shown = request.get_param_value("path");
    std::vector<std::string> outputs;  // export: the files to write
    if (kind == Job::kExport) {
      const std::string format = request.get_param_value("format");
      if (std::find(kExportFormats.begin(), kExportFormats.end(), format) == kExportFormats.end()) {
        return refuse(response, 400, "unknown export format '" + format + "'");
      }
      outputs.push_back("exports/" + stem_of(*path) + "." + format);
    }
    const Draft draft(*path, request.body);
    if (!draft.error().empty()) return refuse(response, 500, draft.error());
    const bool footprints = is_footprint_file(*path);
    std::vector<std::string> args{kind == Job::kCheck ? "check" : (footprints ? "mass" : "build"),
                                  draft.path().filename().string()};
    const fs::path out = fs::temp_directory_path() / ("insula-studio-" + random_token());
    if (kind != Job::kCheck) {
      fs::create_directories(out);
      args.insert(args.end(), {"--report", (out / "report.json").string(), "--quiet"});
      if (kind == Job::kBuild) {
        args.insert(args.end(), {"-o", (out / "model.glb").string()});
        // A city (footprints, or rules on lots) as one mesh: a node per building would make the
        // browser draw thousands of meshes; its parts stay pickable through their feature ids.
        if (footprints || request.has_param("lot")) {
          args.insert(args.end(), {"--gltf-nodes", "scene"});
        }
        // A .bldg building's floor plans, storey by storey, beside the model.
        if (path->extension() == ".bldg")
          args.insert(args.end(), {"-o", (out / "plan.svg").string()});
      } else {
        fs::create_directories(workspace_.root() / "exports");
        for (const std::string& o : outputs)
          args.insert(args.end(), {"-o", (workspace_.root() / o).string()});
      }
      if (request.has_param("lot") && !footprints) {
        std::string why;
        const std::optional<fs::path> lot = workspace_.resolve(request.get_param_value("lot"), why);
        if (!lot) {
          fs::remove_all(out);
          return refuse(response, 403, "refused: lot " + why);
        }
        args.insert(args.end(), {"--lot", lot->string()});
      }
      if (request.has_param("seed") && !footprints) {
        args.insert(args.end(), {"--seed", request.get_param_value("seed")});
      }
    }
    const char* key = kind == Job::kCheck ? "check:" : kind == Job::kBuild ? "build:" : "export:";
    const JobResult job = jobs_.run(key + shown, args, draft.path().parent_path());
    const std::string output = as_shown(job.output, draft.path().filename().string(), shown);
    Json body = {{"exit", job.exit_code},
                 {"cancelled", job.cancelled},
                 {"timed_out", job.timed_out},
                 {"signal", job.signal},
                 {"ok", job.exit_code == 0},
                 {"diagnostics", diagnostics_of(output)},
                 {"output", output}};
    if (kind != Job::kCheck && job.exit_code == 0) {
      body["report"] = Json::parse(read_text(out / "report.json"), nullptr, false);
    }
    if (kind == Job::kBuild && job.exit_code == 0) {
      const bool plan = fs::exists(out / "plan.svg");
      const std::uint64_t id =
          keep_build({read_text(out / "model.glb"), plan ? read_text(out / "plan.svg") : ""});
      body["model"] = "/api/model/" + std::to_string(id) + ".glb";
      if (plan) body["plan"] = "/api/model/" + std::to_string(id) + ".svg";
    }
    if (kind == Job::kExport && job.exit_code == 0) body["files"] = written(outputs);
    std::error_code ignored;
    fs::remove_all(out, ignored);
    reply_json(response, body);
  }

  // A stochastic building (seed 000 §4.3, `insula random --count 1`): its grammar and its model,
  // from the request's seed, shape, parts and rooms (or room list), each checked before use.
  void random_building(const httplib::Request& request, httplib::Response& response) {
    static const std::regex kNumber(R"(\d{1,18})");
    static const std::regex kShape("L|U|T|H|convex");
    static const std::regex kRooms(R"(\d{1,2}-\d{1,2})");
    static const std::regex kRoomList(R"([a-z_]+(,[a-z_]+)*)");
    std::vector<std::string> args{"random", "--count", "1", "-q"};
    const auto option = [&](const char* name, const char* flag, const std::regex& valid) {
      if (!request.has_param(name)) return true;
      const std::string value = request.get_param_value(name);
      if (!std::regex_match(value, valid)) return false;
      args.insert(args.end(), {flag, value});
      return true;
    };
    if (!option("seed", "--seed", kNumber) || !option("shape", "--shape", kShape) ||
        !option("parts", "--parts", kNumber) || !option("rooms", "--rooms", kRooms) ||
        !option("room_list", "--room-list", kRoomList)) {
      return refuse(response, 400,
                    "random: seed, shape (L U T H convex), parts, rooms (MIN-MAX) "
                    "or room_list (types, comma-separated) not understood");
    }
    const fs::path out = fs::temp_directory_path() / ("insula-studio-" + random_token());
    args.insert(args.end(), {"-o", out.string()});
    const JobResult job = jobs_.run("random", args, workspace_.root());
    Json body = {{"exit", job.exit_code},
                 {"cancelled", job.cancelled},
                 {"ok", job.exit_code == 0},
                 {"output", job.output}};
    if (job.exit_code == 0) {
      body["bldg"] = read_text(out / "building_000.bldg");
      const std::uint64_t id = keep_build({read_text(out / "building_000.glb"), ""});
      body["model"] = "/api/model/" + std::to_string(id) + ".glb";
    }
    std::error_code ignored;
    fs::remove_all(out, ignored);
    reply_json(response, body);
  }

  // The exported files and what the writers put beside them (an OBJ's .mtl and origin), as the
  // folder's relative paths.
  Json written(const std::vector<std::string>& outputs) const {
    Json files = Json::array();
    for (const std::string& o : outputs) {
      const fs::path file = workspace_.root() / o;
      const std::string stem =
          file.filename().string().substr(0, file.filename().string().find('.'));
      for (const fs::directory_entry& e : fs::directory_iterator(file.parent_path())) {
        if (e.path().filename().string().starts_with(stem + ".")) {
          files.push_back(e.path().lexically_relative(workspace_.root()).generic_string());
        }
      }
    }
    std::sort(files.begin(), files.end());
    return files;
  }

  struct Built {
    std::string glb;
    std::string svg;  // a .bldg building's plans; else empty
  };

  std::uint64_t keep_build(Built files) {
    std::lock_guard lock(builds_mutex_);
    builds_.emplace_back(++last_build_, std::move(files));
    if (builds_.size() > kModelsKept) builds_.pop_front();
    return last_build_;
  }

  std::string built_file(std::uint64_t id, bool glb) {
    std::lock_guard lock(builds_mutex_);
    for (const auto& [build, files] : builds_) {
      if (build == id) return glb ? files.glb : files.svg;
    }
    return {};
  }

  const StudioOptions& options_;
  Workspace workspace_;
  Jobs jobs_;
  std::mutex builds_mutex_;
  std::deque<std::pair<std::uint64_t, Built>> builds_;
  std::uint64_t last_build_ = 0;
};

}  // namespace

int serve(const StudioOptions& given) {
  StudioOptions options = given;
  if (options.token.empty()) options.token = random_token();
  std::error_code error;
  if (!fs::is_directory(options.folder, error)) {
    std::fprintf(stderr, "insula: error: %s: not a folder\n", options.folder.c_str());
    return 1;
  }
  Studio studio(options, Workspace(options.folder));
  httplib::Server server;
  studio.routes(server);
  const int port = options.port > 0 && server.bind_to_port(options.host.c_str(), options.port)
                       ? options.port
                   : options.port == 0 ? server.bind_to_any_port(options.host.c_str())
                                       : -1;
  if (port < 0) {
    std::fprintf(stderr, "insula: error: cannot listen on %s:%d\n", options.host.c_str(),
                 options.port);
    return 1;
  }
  std::printf("insula studio: http://%s:%d/?token=%s\n", options.host.c_str(), port,
              options.token.c_str());
  std::fflush(stdout);
  std::atomic<bool> done{false};
  std::thread watcher([&] {
    while (!done) {
      if (options.stop_requested && options.stop_requested()) {
        server.stop();
        return;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  });
  server.listen_after_bind();
  done = true;
  watcher.join();
  return 0;
}

}  // namespace insula::studio
