#pragma once
/// @file KeyTable.h
/// The loader's one mechanism: every object of the format is described by a table of keys, and
/// one generic function reads any object against its table.
///
/// A row is (key, presence, default, reader). readObject
///   1. checks that the value is an object;
///   2. rejects any key that is not in the table: a key of a stage this build does not have is
///      named with that stage ("needs stage05_lighting"), any other gets the nearest known one;
///   3. walks the table in order: a present key goes to its reader; an absent required key is
///      an error; an absent key with a default gets its default (JSON text, parsed once when the
///      table is built) through the same reader, so defaults obey the same rules as the file.
/// Objects with a "type" (lights, geometries) pick their table from a second table of types.
///
/// The tables are assembled from the key catalogue (Format.h: every key of every stage, in the
/// documented order) and the readers the format's parts attach (one part per stage present).

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "Node.h"
#include "Readers.h"
#include "common/NearestName.h"

namespace rt::scenefile {

enum class Presence {
  Required,   ///< the key must be given
  Defaulted,  ///< when absent, its default (a JSON value) is read as if the file gave it
  Optional,   ///< when absent, nothing is read (the reader's target keeps its "none")
};

template <typename Target>
struct Key {
  using Reader = std::function<void(const Node& value, Target& target)>;

  /// @param defaultText for Defaulted, the default as JSON text; for Optional, a phrase for the
  ///        documentation ("none"); for Required, empty.
  Key(std::string_view keyName, Presence keyPresence, std::string_view keyDefault, Reader reader)
      : name(keyName),
        presence(keyPresence),
        defaultText(keyDefault),
        read(std::move(reader)),
        defaultValue(keyPresence == Presence::Defaulted ? Json::parse(keyDefault) : Json()) {}

  std::string_view name;
  Presence presence;
  std::string_view defaultText;
  Reader read;
  Json defaultValue;
};

/// A key the format has but this build does not read: its stage is not in the build.
struct AbsentKey {
  std::string_view name;
  std::string_view stage;
};

template <typename Target>
struct KeyTable {
  std::vector<Key<Target>> keys;
  std::vector<AbsentKey> absent;
};

/// The names of a table's keys, plus extra ones (the "type" of a typed object).
template <typename Target>
std::vector<std::string_view> keyNames(const KeyTable<Target>& table,
                                       std::initializer_list<std::string_view> extra = {}) {
  std::vector<std::string_view> names(extra);
  for (const Key<Target>& key : table.keys) names.push_back(key.name);
  return names;
}

/// The unknown-key error of an object read against its table: for a key of a stage this build
/// lacks, "the key 'lights' needs stage05_lighting, which this build does not include"; else
/// "unknown key 'raduis'; did you mean 'radius'?" or, with no near name, the known keys.
template <typename Target>
[[noreturn]] void failUnknownKey(const Node& member, std::string_view key,
                                 const KeyTable<Target>& table,
                                 std::span<const std::string_view> names) {
  for (const AbsentKey& a : table.absent)
    if (a.name == key) member.failAtKey(needsStageMessage("key", key, a.stage));
  const std::string near = didYouMean(key, names);
  member.failAtKey("unknown key" +
                   (near.empty() ? "; expected one of: " + joinNames(names) : near));
}

/// Reads node (an object) into target with table; keys in also are accepted and skipped (the
/// caller has read them). what names the object in the "expected" message ("a camera object").
template <typename Target>
void readObject(const Node& node, const KeyTable<Target>& table, Target& target,
                std::string_view what, std::initializer_list<std::string_view> also = {}) {
  if (!node.json().is_object()) node.expected(what);
  const std::vector<std::string_view> names = keyNames(table, also);
  node.forEachMember([&](std::string_view key, const Node& member) {
    if (std::find(names.begin(), names.end(), key) == names.end())
      failUnknownKey(member, key, table, names);
  });
  for (const Key<Target>& key : table.keys) {
    if (node.find(key.name)) {
      key.read(node.member(key.name), target);
    } else if (key.presence == Presence::Required) {
      node.fail("missing required key '" + std::string(key.name) + "'");
    } else if (key.presence == Presence::Defaulted) {
      key.read(node.defaulted(key.name, key.defaultValue), target);
    }
  }
}

/// One type of a typed object: its name, its table, and what to do with the fields read.
template <typename Fields>
struct TypeRule {
  std::string_view type;
  const KeyTable<Fields>* keys;
  /// Builds the object from the fields (node is the whole object, for messages).
  std::function<void(const Node& node, Fields& fields)> build;
};

/// Reads an object with a "type" key: picks the rule for its type ("expected a WHAT type
/// (a, b, c)" otherwise; for a type of a stage this build does not have, "the WHAT type 'mesh'
/// needs mini2_bvh, ..."), reads the rest of the object with that rule's table, and builds.
template <typename Fields>
void readTyped(const Node& node, const std::vector<TypeRule<Fields>>& rules, std::string_view what,
               std::span<const AbsentKey> absentTypes = {}) {
  if (!node.json().is_object()) node.expected("a " + std::string(what) + " object");
  if (!node.find("type")) node.fail("missing required key 'type'");
  const Node typeNode = node.member("type");
  if (typeNode.json().is_string())
    for (const AbsentKey& a : absentTypes)
      if (typeNode.json().get<std::string>() == a.name)
        typeNode.fail(needsStageMessage(std::string(what) + " type", a.name, a.stage));
  std::vector<std::string_view> types;
  for (const TypeRule<Fields>& rule : rules) types.push_back(rule.type);
  const std::string type =
      readChoice(typeNode, std::string("a ") + std::string(what) + " type", types);
  Fields fields{};
  for (const TypeRule<Fields>& rule : rules)
    if (rule.type == type) {
      readObject(node, *rule.keys, fields, what, {"type"});
      rule.build(node, fields);
      return;
    }
}

}  // namespace rt::scenefile
