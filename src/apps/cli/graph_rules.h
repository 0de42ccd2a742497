// The front-ends behind a graph's rule nodes (lang/graph RuleRunner): CGA rule files, .bldg
// grammars and Lua programs run on a shape's footprint, each program read and checked once from
// the graph's folder (confined like assets), the models returned as parts.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "lang/graph/executor.h"
#include "shape/operation.h"

namespace insula::cli {

class FrontEndRules : public lang::graph::RuleRunner {
 public:
  // `folder`: the graph's folder; `attributes`: the graph's attribute names (CGA reads them as
  // lot properties); `assets` for CGA's i().
  FrontEndRules(std::string folder, std::vector<std::string> attributes,
                const shape::AssetProvider* assets);
  ~FrontEndRules() override;

  bool prepare(const lang::graph::RuleRequest& request, std::string& error) const override;
  std::shared_ptr<const lang::graph::Model> run(const lang::graph::RuleRequest& request,
                                                std::string& error) const override;

  struct Program;  // one read and checked program (graph_rules.cc)

 private:
  const Program* find(const lang::graph::RuleRequest& request) const;

  std::string folder_;
  std::vector<std::string> attributes_;
  const shape::AssetProvider* assets_;
  mutable std::mutex mutex_;
  mutable std::map<std::string, std::unique_ptr<Program>> programs_;  // by language:file#start
};

}  // namespace insula::cli
