// A closed set of named choices, declared once: each entry's name (what scene files, options and
// messages say), its value, and a few words for --help. One table per set (integrators, pixel
// samplers, tone curves, texture filters, stereo modes, sample positions, secondary shadow rules,
// instruction sets) answers every question asked of it: parse a name, name a value, list the
// names for a message, and the text --help shows. No list of names is written twice.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rt {

template <class T>
struct NameEntry {
  std::string_view name;
  T value;
  std::string_view help;  // a few words: "highlights rolled off (ACES fit)"
};

template <class T>
class NameTable {
 public:
  constexpr NameTable(std::span<const NameEntry<T>> entries) : entries_(entries) {}

  std::span<const NameEntry<T>> entries() const { return entries_; }
  size_t size() const { return entries_.size(); }

  const NameEntry<T>* find(std::string_view name) const {
    for (const NameEntry<T>& e : entries_)
      if (e.name == name) return &e;
    return nullptr;
  }
  std::optional<T> parse(std::string_view name) const {
    const NameEntry<T>* e = find(name);
    return e ? std::optional<T>(e->value) : std::nullopt;
  }
  // The name of `value` ("" if no entry holds it): for tables of enums.
  std::string_view name(T value) const {
    for (const NameEntry<T>& e : entries_)
      if (e.value == value) return e.name;
    return {};
  }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const NameEntry<T>& e : entries_) out.emplace_back(e.name);
    return out;
  }
  // "a, b, c", for messages ("expected one of: ...").
  std::string list() const {
    std::string out;
    for (const NameEntry<T>& e : entries_) out += (out.empty() ? "" : ", ") + std::string(e.name);
    return out;
  }
  // "a: its help; b: its help", for --help (an entry without help shows its name alone).
  std::string help() const {
    std::string out;
    for (const NameEntry<T>& e : entries_) {
      if (!out.empty()) out += "; ";
      out += std::string(e.name);
      if (!e.help.empty()) out += ": " + std::string(e.help);
    }
    return out;
  }

 private:
  std::span<const NameEntry<T>> entries_;
};

}  // namespace rt
