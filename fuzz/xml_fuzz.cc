// libFuzzer target for the BuildingGen XML reader alone (lang/cga/xml_reader.h, seed 004 §VII):
// cga_fuzz feeds every input to both the CGA parser and this reader, but its mutations start from
// grammars; this target starts from the XML corpus (fuzz/corpus/xml) so that the reader's
// elements, attributes and expressions get the whole budget. The contract is cga_fuzz's
// check_xml_reader: a failure carries exactly one positioned CGA5xx error, a success prints to
// CGA text that parses again.
#define INSULA_FUZZ_NO_ENTRY
#include "cga_fuzz.cc"
#undef INSULA_FUZZ_NO_ENTRY

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string problem =
      insula::fuzz::check_xml_reader(std::string_view(reinterpret_cast<const char*>(data), size));
  if (!problem.empty()) {
    std::fprintf(stderr, "xml_fuzz: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}

#ifdef INSULA_FUZZ_REPLAY
#define INSULA_FUZZ_REPLAY_NAME "xml_fuzz_replay"
#include "replay_main.h"
#endif
