#pragma once
/// @file Node.h
/// A value of the document being read, with what an error message needs: its JSON path (built
/// only when an error is reported, from the chain of parents) and its position in the text.

#include <any>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <typeindex>

#include <nlohmann/json.hpp>

#include "SourceMap.h"
#include "scenefile/ModelFile.h"
#include "scenefile/SceneDocument.h"

namespace rt::scenefile {

using Json = nlohmann::ordered_json;

/// What every reader shares: the text and its positions for messages, and the document being
/// built (a geometry's "material" looks up the materials read before it).
struct Context {
  Context(std::string_view sourceText, std::string sourceName, const SourceMap& sourceMap)
      : text(sourceText), source(std::move(sourceName)), map(sourceMap) {}

  std::string_view text;
  std::string source;
  const SourceMap& map;
  SceneDocument doc;
  /// Where the meshes' model files are read (the disk unless parseScene was told otherwise).
  ModelFileSource models;

  /// What a part of the format keeps while it reads (stage 5: its index of the appearance
  /// table's rows), one value per type.
  template <typename T>
  T& state() {
    std::any& slot = states_[std::type_index(typeid(T))];
    if (!slot.has_value()) slot = T{};
    return std::any_cast<T&>(slot);
  }

 private:
  std::map<std::type_index, std::any> states_;
};

class Node {
 public:
  /// The document's root value.
  Node(Context& ctx, const Json& root) : ctx_(&ctx), json_(&root), entry_(0) {}

  const Json& json() const { return *json_; }
  Context& context() const { return *ctx_; }

  /// The member key of this object; nullptr when absent. Precondition: json() is an object.
  const Json* find(std::string_view key) const;
  /// The member key, which must be present.
  Node member(std::string_view key) const;
  /// A node for a key absent from the file, carrying value (its default) at key's path.
  Node defaulted(std::string_view key, const Json& value) const;

  /// Calls f(element) for every element of this array, in order.
  template <typename F>
  void forEachElement(F&& f) const {
    std::uint32_t entry = firstChild();
    std::size_t i = 0;
    for (const Json& value : *json_) {
      f(Node(*this, value, entry, {}, i++));
      entry = nextSibling(entry);
    }
  }
  /// Calls f(key, member) for every member of this object, in the file's order.
  template <typename F>
  void forEachMember(F&& f) const {
    std::uint32_t entry = firstChild();
    for (auto it = json_->begin(); it != json_->end(); ++it) {
      f(std::string_view(it.key()), Node(*this, it.value(), entry, it.key(), 0));
      entry = nextSibling(entry);
    }
  }

  /// "geometries[3].radius"; "" for the document.
  std::string path() const;
  /// The value as the file wrote it (numbers in the file's own spelling), shortened when long.
  std::string describe() const;

  /// "FILE:LINE:COL: PATH: detail" at this value's position: what fail() reports (for a
  /// warning).
  std::string message(const std::string& detail) const;
  /// Throws a SceneError at this value's position: "FILE:LINE:COL: PATH: detail".
  [[noreturn]] void fail(const std::string& detail) const;
  /// As fail, but at the member's key ("unknown key", "duplicate key") when it has one.
  [[noreturn]] void failAtKey(const std::string& detail) const;
  /// fail("expected WHAT, got VALUE").
  [[noreturn]] void expected(std::string_view what) const;

 private:
  Node(const Node& parent, const Json& value, std::uint32_t entry, std::string_view key,
       std::size_t index)
      : ctx_(parent.ctx_),
        json_(&value),
        entry_(entry),
        parent_(&parent),
        key_(key),
        index_(index) {}

  std::uint32_t firstChild() const;
  std::uint32_t nextSibling(std::uint32_t entry) const;
  [[noreturn]] void failAt(std::uint32_t offset, const std::string& detail) const;
  /// The offset fail() reports at: the value's own, or, for a default value (which has none),
  /// the nearest parent's.
  std::uint32_t reportedOffset() const;

  Context* ctx_;
  const Json* json_;
  std::uint32_t entry_;           ///< index in the source map; NONE for a default value
  const Node* parent_ = nullptr;  ///< nullptr for the root
  std::string_view key_;          ///< the member's key when the parent is an object
  std::size_t index_ = 0;         ///< the element's index when the parent is an array
};

}  // namespace rt::scenefile
