// `insula studio [DIR] [--port N] [--host H]` (issue 15; docs/studio.md): a local web server on
// DIR's files. It binds to 127.0.0.1 unless told otherwise and answers only requests that carry
// the random token it prints at start (`?token=` or the `X-Insula-Token` header), as Jupyter does.
// The API lists, reads and saves DIR's files and checks and builds a file's edited text as child
// processes of this binary (jobs.h); web/ (the page) is served beside it.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace insula::studio {

struct StudioOptions {
  std::string folder = ".";
  std::string host = "127.0.0.1";
  int port = 0;                          // 0: any free port
  std::filesystem::path executable;      // the insula binary (checks and builds run it)
  std::filesystem::path web;             // the page's files; empty: API only
  std::string token;                     // empty: a random one
  std::function<bool()> stop_requested;  // polled; true stops the server
};

// Serves until stop_requested() says so; prints `insula studio: http://HOST:PORT/?token=TOKEN` on
// stdout once listening. Returns the exit code (1 when the folder or the port is unusable).
int serve(const StudioOptions& options);

}  // namespace insula::studio
