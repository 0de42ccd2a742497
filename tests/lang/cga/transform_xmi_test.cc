// The XMI export conforms to the shipped Ecore metamodel docs/cga.ecore (seed 004 §IV): for every
// grammar file, each element of the XMI is a containment feature of its parent's EClass, its
// xsi:type (or the feature's type) is a concrete subclass of the feature's type, and each XML
// attribute is an EAttribute of that class with a value of the attribute's type (EInt, EDouble,
// EBoolean, enum literal). Both files are read with pugixml.
#include <gtest/gtest.h>
#include <pugixml.hpp>

#include <charconv>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "lang/cga/model_xmi.h"
#include "test_util.h"

namespace insula::lang::cga {
namespace {

using testing::data_dir;
using testing::files_in;
using testing::read_file;

struct Feature {
  bool reference = false;
  bool containment = false;
  bool many = false;
  std::string type;  // class or enum name, or EInt / EDouble / EBoolean / EString
};

struct EClass {
  bool abstract = false;
  std::vector<std::string> supers;
  std::map<std::string, Feature> features;
};

struct Ecore {
  std::string ns_uri;
  std::map<std::string, EClass> classes;
  std::map<std::string, std::set<std::string>> enums;

  bool is_subclass(const std::string& sub, const std::string& super) const {
    if (sub == super) return true;
    const auto it = classes.find(sub);
    if (it == classes.end()) return false;
    for (const std::string& s : it->second.supers) {
      if (is_subclass(s, super)) return true;
    }
    return false;
  }

  const Feature* feature(const std::string& eclass, const std::string& name) const {
    const auto it = classes.find(eclass);
    if (it == classes.end()) return nullptr;
    if (const auto f = it->second.features.find(name); f != it->second.features.end()) {
      return &f->second;
    }
    for (const std::string& s : it->second.supers) {
      if (const Feature* f = feature(s, name)) return f;
    }
    return nullptr;
  }
};

// "#//Located" -> "Located"; "ecore:EDataType http://...Ecore#//EInt" -> "EInt".
std::string type_name(const std::string& reference) {
  const std::size_t at = reference.rfind("//");
  return at == std::string::npos ? reference : reference.substr(at + 2);
}

Ecore load_ecore() {
  pugi::xml_document doc;
  const std::string path = std::string(INSULA_SOURCE_DIR) + "/docs/cga.ecore";
  EXPECT_TRUE(doc.load_file(path.c_str())) << path;
  Ecore ecore;
  const pugi::xml_node package = doc.child("ecore:EPackage");
  ecore.ns_uri = package.attribute("nsURI").value();
  for (pugi::xml_node c : package.children("eClassifiers")) {
    const std::string kind = c.attribute("xsi:type").value();
    const std::string name = c.attribute("name").value();
    if (kind == "ecore:EEnum") {
      for (pugi::xml_node literal : c.children("eLiterals")) {
        ecore.enums[name].insert(literal.attribute("name").value());
      }
      continue;
    }
    EXPECT_EQ(kind, "ecore:EClass") << name;
    EClass& eclass = ecore.classes[name];
    eclass.abstract = c.attribute("abstract").as_bool();
    const std::string supers = c.attribute("eSuperTypes").value();
    for (std::size_t at = 0; at < supers.size();) {
      const std::size_t end = std::min(supers.find(' ', at), supers.size());
      eclass.supers.push_back(type_name(supers.substr(at, end - at)));
      at = end + 1;
    }
    for (pugi::xml_node f : c.children("eStructuralFeatures")) {
      Feature feature;
      feature.reference = std::string(f.attribute("xsi:type").value()) == "ecore:EReference";
      feature.containment = f.attribute("containment").as_bool();
      feature.many = f.attribute("upperBound").as_int(1) == -1;
      feature.type = type_name(f.attribute("eType").value());
      eclass.features[f.attribute("name").value()] = feature;
    }
  }
  return ecore;
}

class Conformance {
 public:
  explicit Conformance(const Ecore& ecore) : ecore_(ecore) {}

  // Empty when `node`, an instance of `eclass`, conforms; else the first problem, with a path.
  std::string check(pugi::xml_node node, const std::string& eclass, const std::string& path) {
    if (!ecore_.classes.count(eclass)) return path + ": unknown class " + eclass;
    if (ecore_.classes.at(eclass).abstract) return path + ": abstract class " + eclass;
    ++checked_[eclass];
    for (pugi::xml_attribute a : node.attributes()) {
      const std::string name = a.name();
      if (name == "xsi:type" || name.rfind("xmlns", 0) == 0 || name.rfind("xmi:", 0) == 0) continue;
      const Feature* f = ecore_.feature(eclass, name);
      if (!f || f->reference) return path + ": " + eclass + " has no attribute " + name;
      if (std::string problem = value(*f, a.value()); !problem.empty()) {
        return path + "@" + name + ": " + problem;
      }
    }
    std::map<std::string, int> counts;
    for (pugi::xml_node child : node.children()) {
      if (child.type() != pugi::node_element) continue;
      const std::string name = child.name();
      const Feature* f = ecore_.feature(eclass, name);
      if (!f || !f->reference || !f->containment) {
        return path + ": " + eclass + " has no containment " + name;
      }
      if (++counts[name] > 1 && !f->many) return path + ": " + name + " is single-valued";
      std::string type = f->type;
      if (pugi::xml_attribute xsi = child.attribute("xsi:type")) {
        const std::string written = xsi.value();
        if (written.rfind("cga:", 0) != 0) return path + ": xsi:type without cga prefix";
        type = written.substr(4);
        if (!ecore_.is_subclass(type, f->type)) {
          return path + ": " + type + " is not a " + f->type;
        }
      }
      if (std::string problem = check(child, type, path + "/" + name); !problem.empty()) {
        return problem;
      }
    }
    return {};
  }

  const std::map<std::string, int>& checked() const { return checked_; }

 private:
  std::string value(const Feature& f, const std::string& text) const {
    if (f.type == "EString") return {};
    if (f.type == "EBoolean") {
      return text == "true" || text == "false" ? "" : "not a boolean: " + text;
    }
    if (f.type == "EInt" || f.type == "EDouble") {
      double v = 0;
      const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
      if (ec != std::errc() || end != text.data() + text.size()) return "not a number: " + text;
      if (f.type == "EInt" && v != static_cast<double>(static_cast<long long>(v))) {
        return "not an integer: " + text;
      }
      return {};
    }
    const auto e = ecore_.enums.find(f.type);
    if (e == ecore_.enums.end()) return "unknown attribute type " + f.type;
    return e->second.count(text) ? "" : "not a literal of " + f.type + ": " + text;
  }

  const Ecore& ecore_;
  std::map<std::string, int> checked_;
};

TEST(CgaXmi, EcoreIsConsistent) {
  const Ecore ecore = load_ecore();
  EXPECT_EQ(ecore.ns_uri, kCgaNsUri);
  ASSERT_GE(ecore.classes.size(), 30U);
  for (const auto& [name, eclass] : ecore.classes) {
    for (const std::string& s : eclass.supers) {
      EXPECT_TRUE(ecore.classes.count(s)) << name;
    }
    for (const auto& [feature, f] : eclass.features) {
      if (f.reference) {
        EXPECT_TRUE(ecore.classes.count(f.type)) << name << "." << feature;
      }
    }
  }
}

TEST(CgaXmi, EveryGrammarConformsToTheEcore) {
  const Ecore ecore = load_ecore();
  Conformance conformance(ecore);
  std::vector<std::filesystem::path> files = files_in(data_dir(), ".cga");
  for (const auto& p : files_in(data_dir() / "transform", ".cga")) files.push_back(p);
  for (const auto& path : files) {
    const base::Source source(path.filename().string(), read_file(path));
    const base::Result<Grammar> g = parse(source);
    ASSERT_TRUE(g.ok()) << path;
    const std::string xmi = model_xmi(g.value(), source);
    pugi::xml_document doc;
    ASSERT_TRUE(doc.load_string(xmi.c_str())) << path;
    const pugi::xml_node root = doc.document_element();
    EXPECT_STREQ(root.name(), "cga:ShapeGrammar");
    EXPECT_STREQ(root.attribute("xmi:version").value(), "2.0");
    EXPECT_STREQ(root.attribute("xmlns:cga").value(), kCgaNsUri);
    EXPECT_EQ(conformance.check(root, "ShapeGrammar", path.filename().string()), "");
  }
  // Every concrete class of the metamodel occurs in the test grammars, so each is exercised.
  for (const auto& [name, eclass] : ecore.classes) {
    if (!eclass.abstract) {
      EXPECT_TRUE(conformance.checked().count(name)) << name;
    }
  }
}

TEST(CgaXmi, NonConformingXmiIsCaught) {
  // The checker itself must fail on a wrong feature, a wrong subtype and a bad enum literal.
  const Ecore ecore = load_ecore();
  Conformance conformance(ecore);
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(
      "<r><prioritySets priority='1'><rules predecessor='A'><ruleParts>"
      "<successors xsi:type='cga:NumberLiteral'/></ruleParts></rules></prioritySets></r>"));
  EXPECT_EQ(conformance.check(doc.first_child(), "ShapeGrammar", "x"),
            "x/prioritySets/rules/ruleParts: NumberLiteral is not a Successor");
  ASSERT_TRUE(
      doc.load_string("<r><attributes name='h'><value xsi:type='cga:UnaryExpression' "
                      "operator='plus'/></attributes></r>"));
  EXPECT_EQ(conformance.check(doc.first_child(), "ShapeGrammar", "x"),
            "x/attributes/value@operator: not a literal of UnaryOperator: plus");
  ASSERT_TRUE(doc.load_string("<r><rules/></r>"));
  EXPECT_EQ(conformance.check(doc.first_child(), "ShapeGrammar", "x"),
            "x: ShapeGrammar has no containment rules");
}

}  // namespace
}  // namespace insula::lang::cga
