#include "apps/studio/server.h"

#include <httplib.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <charconv>
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

#include "apps/studio/drawing.h"
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

// Text that is not UTF-8 (a file name, a build's output) is shown with replacement characters
// rather than failing the answer.
std::string json_text(const Json& body) {
  return body.dump(-1, ' ', false, Json::error_handler_t::replace);
}

void reply_json(httplib::Response& response, const Json& body, int status = 200) {
  response.status = status;
  response.set_content(json_text(body), kJson);
}

// A temporary folder for a job's outputs, removed with it.
struct TempFolder {
  fs::path path = fs::temp_directory_path() / ("insula-studio-" + random_token());
  TempFolder() {
    std::error_code ignored;
    fs::create_directories(path, ignored);
  }
  ~TempFolder() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;
};

// One of the few checks and builds that may run at once (each holds a server thread until its
// child ends), or none when they are all taken.
class JobSlot {
 public:
  static constexpr int kJobs = 3;
  explicit JobSlot(std::atomic<int>& running) : running_(running) {
    taken_ = running_.fetch_add(1) < kJobs;
    if (!taken_) running_.fetch_sub(1);
  }
  ~JobSlot() {
    if (taken_) running_.fetch_sub(1);
  }
  JobSlot(const JobSlot&) = delete;
  JobSlot& operator=(const JobSlot&) = delete;
  bool taken() const { return taken_; }

 private:
  std::atomic<int>& running_;
  bool taken_ = false;
};

// A number of a diagnostic line, or nullopt when it is none (or too large).
std::optional<int> line_number(const std::string& text) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
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
    const std::optional<int> row = line_number(m[2].str());
    const std::optional<int> column = line_number(m[3].str());
    if (!row || !column) continue;
    out.push_back({{"file", m[1].str()},
                   {"line", *row},
                   {"column", *column},
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

  void listening_on(int port) { port_ = port; }
  void stop_jobs() { jobs_.stop_all(); }

  void routes(httplib::Server& server) {
    server.set_payload_max_length(kMaxBody);
    server.set_pre_routing_handler(
        [this](const httplib::Request& request, httplib::Response& response) {
          if (request.get_param_value("token") == options_.token) {
            // The page's own files (its script, its style) then come with the cookie.
            // (Named after the port: browsers send a host's cookies to all its ports.)
            response.set_header("Set-Cookie", cookie_name() + "=" + options_.token +
                                                  "; HttpOnly; SameSite=Strict; Path=/");
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
      static const std::string reference = json_text(reference_json());
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
    // The drawing tool's reading of a .bldg text (the editor's, saved or not).
    server.Post("/api/drawing", [](const httplib::Request& request, httplib::Response& response) {
      const std::string name =
          request.has_param("path") ? request.get_param_value("path") : std::string("drawing.bldg");
      reply_json(response, drawing_json(name, request.body));
    });
    server.Post("/api/check", [this](const httplib::Request& request, httplib::Response& response) {
      run_job(request, response, Job::kCheck);
    });
    server.Post("/api/build", [this](const httplib::Request& request, httplib::Response& response) {
      run_job(request, response, Job::kBuild);
    });
    server.Post("/api/report",
                [this](const httplib::Request& request, httplib::Response& response) {
                  run_job(request, response, Job::kReport);
                });
    server.Post("/api/export",
                [this](const httplib::Request& request, httplib::Response& response) {
                  run_job(request, response, Job::kExport);
                });
    server.Get(R"(/api/model/(\d{1,18})\.(glb|svg))",
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
  std::string cookie_name() const { return "insula_token_" + std::to_string(port_); }

  // The token as a header (the page's API calls) or as the cookie set with the page.
  bool authorized(const httplib::Request& request) const {
    if (request.get_header_value("X-Insula-Token") == options_.token) return true;
    const std::string wanted = cookie_name() + "=" + options_.token;
    std::istringstream cookies(request.get_header_value("Cookie"));
    for (std::string cookie; std::getline(cookies, cookie, ';');) {
      const std::size_t start = cookie.find_first_not_of(' ');
      if (start != std::string::npos && cookie.substr(start) == wanted) return true;
    }
    return false;
  }

  std::optional<fs::path> file_of(const httplib::Request& request, httplib::Response& response) {
    std::string why;
    std::optional<fs::path> path = workspace_.resolve(request.get_param_value("path"), why);
    if (!path) refuse(response, 403, "refused: " + why);
    return path;
  }

  enum class Job { kCheck, kBuild, kReport, kExport };

  // Checks (`insula check`), builds (`insula build -o model.glb --report`; footprints: `insula
  // mass`), runs for the report alone (`insula build --report`, no output: the graph editor's
  // counts come before the model is written) or exports (the same build into the folder's
  // `exports/`) the request's body as the text of `path`, with `lot` (a file of the folder) and
  // `seed` for builds.
  void run_job(const httplib::Request& request, httplib::Response& response, Job kind) {
    const std::optional<fs::path> path = file_of(request, response);
    if (!path) return;
    if (!is_studio_file(*path) || fs::is_directory(*path)) {
      return refuse(response, 400, "not a file the studio builds");
    }
    const std::string shown = request.get_param_value("path");
    const JobSlot slot(running_jobs_);
    if (!slot.taken()) return refuse(response, 503, "busy: too many checks and builds at once");
    std::optional<fs::path> exported;  // the export's file
    if (kind == Job::kExport) {
      const std::string format = request.get_param_value("format");
      if (std::find(kExportFormats.begin(), kExportFormats.end(), format) == kExportFormats.end()) {
        return refuse(response, 400, "unknown export format '" + format + "'");
      }
      // Resolved like any request path: an `exports` link leading out is refused.
      std::string why;
      exported = workspace_.resolve("exports/" + stem_of(*path) + "." + format, why);
      std::error_code error;
      if (exported) fs::create_directories(exported->parent_path(), error);
      if (!exported || error || !fs::is_directory(exported->parent_path())) {
        return refuse(response, 403, "refused: exports/ " + (exported ? "is not a folder" : why));
      }
    }
    const Draft draft(*path, request.body);
    if (!draft.error().empty()) return refuse(response, 500, draft.error());
    const bool footprints = is_footprint_file(*path);
    std::vector<std::string> args{kind == Job::kCheck ? "check" : (footprints ? "mass" : "build"),
                                  draft.path().filename().string()};
    const TempFolder temp;
    const fs::path& out = temp.path;
    if (kind != Job::kCheck) {
      args.insert(args.end(), {"--report", (out / "report.json").string(), "--quiet"});
      if (kind == Job::kBuild) {
        args.insert(args.end(), {"-o", (out / "model.glb").string()});
        // A city (footprints, rules on lots, a graph: graphs make districts) as one mesh: a node
        // per building would make the browser draw thousands of meshes; its parts stay
        // pickable through their feature ids.
        if (footprints || request.has_param("lot") ||
            path->filename().string().ends_with(".graph.json")) {
          args.insert(args.end(), {"--gltf-nodes", "scene"});
        }
        // Colours by semantic class (walls, roofs, windows...) rather than the faces' own.
        if (request.get_param_value("colours") == "class") {
          args.insert(args.end(), {"--gltf-colours", "class"});
        }
        // A .bldg building's floor plans, storey by storey, beside the model.
        if (path->extension() == ".bldg") {
          args.insert(args.end(), {"-o", (out / "plan.svg").string()});
        }
      } else if (kind == Job::kExport) {
        args.insert(args.end(), {"-o", exported->string()});
      }
      if (request.has_param("lot") && !footprints) {
        std::string why;
        const std::optional<fs::path> lot = workspace_.resolve(request.get_param_value("lot"), why);
        if (!lot) return refuse(response, 403, "refused: lot " + why);
        args.insert(args.end(), {"--lot", lot->string()});
      }
      if (request.has_param("seed") && !footprints) {
        args.insert(args.end(), {"--seed", request.get_param_value("seed")});
      }
      // The graph editor's selected node: its output entities instead of the results.
      if (request.has_param("probe") && kind == Job::kBuild) {
        args.insert(args.end(), {"--probe", request.get_param_value("probe")});
      }
      // A graph's report lists every result entity (a city's: megabytes); the graph editor's
      // counts and probes list the first ones (its tables show a few) and say how many there were.
      if (path->filename().string().ends_with(".graph.json") &&
          (kind == Job::kReport || request.has_param("probe"))) {
        args.insert(args.end(), {"--report-entities", "1000"});
      }
    }
    const bool probe = request.has_param("probe") && kind == Job::kBuild;
    const char* key = kind == Job::kCheck    ? "check:"
                      : probe                ? "probe:"  // beside the model's build, not over it
                      : kind == Job::kBuild  ? "build:"
                      : kind == Job::kReport ? "report:"
                                             : "export:";
    // Keyed by the resolved file, so `a` and `./a` are one file whose newer edit cancels. A
    // check is never cancelled (a key of its own): its caller asks about one text (may this edge
    // be connected?), and a check reaching the server late must not leave a newer one unanswered.
    // A build beside the graph editor's report run (`behind=1`) yields the cores to it: the
    // counts come first, the model after.
    const std::string job_key = kind == Job::kCheck
                                    ? key + std::to_string(++checks_) + ":" + path->string()
                                    : key + path->string();
    const int niceness = kind == Job::kBuild && request.get_param_value("behind") == "1" ? 10 : 0;
    const JobResult job = jobs_.run(job_key, args, draft.path().parent_path(), niceness);
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
    if (kind == Job::kExport && job.exit_code == 0) body["files"] = written(*exported);
    reply_json(response, body);
  }

  // The exported file and what the writers put beside it (an OBJ's .mtl and origin), as the
  // folder's relative paths.
  Json written(const fs::path& file) const {
    Json files = Json::array();
    const std::string name = file.filename().string();
    const std::string stem = name.substr(0, name.find('.'));
    std::error_code error;
    for (const fs::directory_entry& e : fs::directory_iterator(file.parent_path(), error)) {
      if (e.path().filename().string().starts_with(stem + ".")) {
        files.push_back(e.path().lexically_relative(workspace_.root()).generic_string());
      }
    }
    std::sort(files.begin(), files.end());
    return files;
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
    const JobSlot slot(running_jobs_);
    if (!slot.taken()) return refuse(response, 503, "busy: too many checks and builds at once");
    const TempFolder temp;
    const fs::path out = temp.path / "random";
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
    reply_json(response, body);
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
  int port_ = 0;
  std::atomic<int> running_jobs_{0};
  std::atomic<std::uint64_t> checks_{0};  // numbers each check's job key
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
  studio.listening_on(port);
  std::printf("insula studio: http://%s:%d/?token=%s\n", options.host.c_str(), port,
              options.token.c_str());
  std::fflush(stdout);
  std::atomic<bool> done{false};
  std::thread watcher([&] {
    while (!done) {
      if (options.stop_requested && options.stop_requested()) {
        studio.stop_jobs();  // a build in flight would hold its thread until it ends
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
