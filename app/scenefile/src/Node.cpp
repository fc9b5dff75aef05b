#include "Node.h"

#include <vector>

#include "scenefile/SceneFile.h"

namespace rt::scenefile {

namespace {

constexpr std::size_t DESCRIBE_LIMIT = 60;  ///< longest value quoted in a message

bool isNumberChar(char c) {
  return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
}

/// Writes value compactly into out, numbers as the file spelled them, stopping (with "...")
/// once out is longer than DESCRIBE_LIMIT. Recursion is bounded by the document's depth, which
/// the first pass limits to MAX_DEPTH.
void describeInto(std::string& out, const Json& value, const Context& ctx, std::uint32_t entry) {
  if (out.size() > DESCRIBE_LIMIT) return;
  const auto& entries = ctx.map.entries;
  const bool located = entry < entries.size();
  if (value.is_number() && located) {
    std::size_t end = entries[entry].valueOffset;
    while (end < ctx.text.size() && isNumberChar(ctx.text[end])) ++end;
    out += ctx.text.substr(entries[entry].valueOffset, end - entries[entry].valueOffset);
  } else if (value.is_array()) {
    out += '[';
    std::uint32_t child = located ? entry + 1 : SourceEntry::NONE;
    bool first = true;
    for (const Json& element : value) {
      if (!first) out += ',';
      first = false;
      if (out.size() > DESCRIBE_LIMIT) break;
      describeInto(out, element, ctx, child);
      child = child < entries.size() ? entries[child].end : SourceEntry::NONE;
    }
    out += ']';
  } else if (value.is_object()) {
    out += '{';
    std::uint32_t child = located ? entry + 1 : SourceEntry::NONE;
    bool first = true;
    for (auto it = value.begin(); it != value.end(); ++it) {
      if (!first) out += ',';
      first = false;
      if (out.size() > DESCRIBE_LIMIT) break;
      out += Json(it.key()).dump(-1, ' ', false, Json::error_handler_t::replace);
      out += ':';
      describeInto(out, it.value(), ctx, child);
      child = child < entries.size() ? entries[child].end : SourceEntry::NONE;
    }
    out += '}';
  } else {
    out += value.dump(-1, ' ', false, Json::error_handler_t::replace);
  }
}

}  // namespace

const Json* Node::find(std::string_view key) const {
  const auto it = json_->find(key);
  return it == json_->end() ? nullptr : &*it;
}

Node Node::member(std::string_view key) const {
  std::size_t k = 0;
  for (auto it = json_->begin(); it != json_->end(); ++it, ++k)
    if (it.key() == key) {
      const std::uint32_t entry =
          entry_ == SourceEntry::NONE ? SourceEntry::NONE : ctx_->map.child(entry_, k);
      return Node(*this, it.value(), entry, it.key(), 0);
    }
  throw std::logic_error("Node::member: no key '" + std::string(key) + "' at " + path());
}

Node Node::defaulted(std::string_view key, const Json& value) const {
  return Node(*this, value, SourceEntry::NONE, key, 0);
}

std::uint32_t Node::firstChild() const {
  return entry_ == SourceEntry::NONE ? SourceEntry::NONE : ctx_->map.child(entry_, 0);
}

std::uint32_t Node::nextSibling(std::uint32_t entry) const {
  if (entry >= ctx_->map.entries.size()) return SourceEntry::NONE;
  const std::uint32_t next = ctx_->map.entries[entry].end;
  return next < ctx_->map.entries[entry_].end ? next : SourceEntry::NONE;
}

std::string Node::path() const {
  std::vector<const Node*> chain;
  for (const Node* n = this; n->parent_; n = n->parent_) chain.push_back(n);
  std::string out;
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
    const Node& n = **it;
    if (n.parent_->json_->is_object())
      appendMember(out, n.key_);
    else
      appendElement(out, n.index_);
  }
  return out;
}

std::string Node::describe() const {
  std::string out;
  describeInto(out, *json_, *ctx_, entry_);
  if (out.size() > DESCRIBE_LIMIT) {
    // Cut at a character boundary (never inside a UTF-8 sequence) and mark the cut.
    std::size_t cut = DESCRIBE_LIMIT;
    while (cut > 0 && (static_cast<unsigned char>(out[cut]) & 0xC0) == 0x80) --cut;
    out.resize(cut);
    out += "...";
  }
  return out;
}

void Node::failAt(std::uint32_t offset, const std::string& detail) const {
  int line = 0, column = 0;
  if (offset != SourceEntry::NONE) {
    const LineColumn lc = lineColumnOf(ctx_->text, offset);
    line = lc.line;
    column = lc.column;
  }
  throw SceneError(ctx_->source, line, column, path(), detail);
}

std::uint32_t Node::reportedOffset() const {
  const auto& entries = ctx_->map.entries;
  // A default value has no position of its own: point at the object that lacks the key.
  const Node* located = this;
  while (located && located->entry_ >= entries.size()) located = located->parent_;
  return located ? entries[located->entry_].valueOffset : SourceEntry::NONE;
}

std::string Node::message(const std::string& detail) const {
  const std::uint32_t offset = reportedOffset();
  const LineColumn lc =
      offset == SourceEntry::NONE ? LineColumn{} : lineColumnOf(ctx_->text, offset);
  return SceneError::format(ctx_->source, lc.line, lc.column, path(), detail);
}

void Node::fail(const std::string& detail) const { failAt(reportedOffset(), detail); }

void Node::failAtKey(const std::string& detail) const {
  const auto& entries = ctx_->map.entries;
  if (entry_ < entries.size() && entries[entry_].keyOffset != SourceEntry::NONE)
    failAt(entries[entry_].keyOffset, detail);
  fail(detail);
}

void Node::expected(std::string_view what) const {
  fail("expected " + std::string(what) + ", got " + describe());
}

}  // namespace rt::scenefile
