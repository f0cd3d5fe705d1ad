#pragma once
// Strict reading of the project's JSON files. Every value is read through a
// JsonObject that knows its file and its path inside the file, so that an
// error names both ("data/flights/ascent.json: keyframes[2].time: ...").
// Keys that were never read are errors too: a misspelt key must not be
// silently ignored.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <limits>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace planet {

class JsonObject {
 public:
  // Parses `file` and returns its top-level object, which (with every
  // object taken from it) holds the parsed document.
  static JsonObject load(const std::filesystem::path& file);

  // An object within a document the caller keeps alive.
  JsonObject(const nlohmann::json& value, std::string file, std::string path);

  bool has(const std::string& key) const;

  double number(const std::string& key, double min = -std::numeric_limits<double>::max(),
                double max = std::numeric_limits<double>::max());
  double number_or(const std::string& key, double fallback,
                   double min = -std::numeric_limits<double>::max(),
                   double max = std::numeric_limits<double>::max());
  int integer(const std::string& key, int min, int max);
  int integer_or(const std::string& key, int fallback, int min, int max);
  bool boolean_or(const std::string& key, bool fallback);
  std::string string(const std::string& key);
  std::string string_or(const std::string& key, const std::string& fallback);
  // A fixed-length array of numbers, each within [min, max].
  std::vector<double> numbers(const std::string& key, size_t count,
                              double min = -std::numeric_limits<double>::max(),
                              double max = std::numeric_limits<double>::max());
  // An array of numbers of any non-zero length.
  std::vector<double> number_list(const std::string& key,
                                  double min = -std::numeric_limits<double>::max(),
                                  double max = std::numeric_limits<double>::max());
  JsonObject object(const std::string& key);
  std::vector<JsonObject> objects(const std::string& key);
  // The raw value, for a sub-object another module parses.
  const nlohmann::json& raw(const std::string& key);

  // Throws on any key that was not read.
  void finish() const;

  // An InputError about this object or one of its keys.
  [[noreturn]] void fail(const std::string& key, const std::string& reason) const;
  [[noreturn]] void fail(const std::string& reason) const;

  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }

 private:
  const nlohmann::json& require(const std::string& key);
  std::string where(const std::string& key) const;

  JsonObject(std::shared_ptr<const nlohmann::json> document, const nlohmann::json& value,
             std::string file, std::string path);

  std::shared_ptr<const nlohmann::json> document_;  // null where the caller keeps it
  const nlohmann::json* value_;
  std::string file_;
  std::string path_;
  std::set<std::string> read_;
};

}  // namespace planet
