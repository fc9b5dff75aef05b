// libFuzzer target: parseScene on arbitrary bytes. The loader's contract is that any input
// gives a document or a SceneError; anything else (another exception, a sanitizer report, a
// hang, an allocation beyond -rss_limit_mb) is a bug, and libFuzzer keeps the input that
// caused it. When it returns a document, the export must read back to the same text.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "scenefile/SceneFile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  rt::SceneDocument doc;
  try {
    doc = rt::parseScene(text, "fuzz.json");
  } catch (const rt::SceneError&) {
    return 0;  // rejected with a message: fine
  }
  // Accepted: the round trip must hold (a failure here aborts, so libFuzzer keeps the input).
  const std::string once = rt::dumpScene(doc);
  const std::string twice = rt::dumpScene(rt::parseScene(once, "fuzz-export.json"));
  if (once != twice) std::abort();
  return 0;
}
