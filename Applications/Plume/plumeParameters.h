// Strict, typed access to one JSON object of a scene: every key read is
// checked for type and range, and keys nobody asked for are reported as
// unknown parameters (typos must not be silently ignored).
#ifndef plumeParameters_h
#define plumeParameters_h

#include <nlohmann/json.hpp>

#include <array>
#include <set>
#include <string>
#include <vector>

class vtkObject;
class vtkPlumeParameterTable;

namespace plume
{
class Parameters
{
public:
  /** `where` names the object in messages, e.g. "representations[1] (glyphs)". */
  Parameters(const nlohmann::json& object, std::string where);

  bool Has(const std::string& key) const;
  double Number(const std::string& key, double fallback, double min = -1e300, double max = 1e300);
  int Integer(const std::string& key, int fallback, int min, int max);
  bool Boolean(const std::string& key, bool fallback);
  std::string String(const std::string& key, const std::string& fallback);
  /** A string that must be one of `choices`. */
  std::string Choice(const std::string& key, const std::string& fallback, const std::vector<std::string>& choices);
  /** A list of exactly N finite numbers. */
  template <size_t N>
  std::array<double, N> Vector(const std::string& key, const std::array<double, N>& fallback);
  /** An RGB colour: 3 numbers in [0, 1]. */
  std::array<double, 3> Color(const std::string& key, const std::array<double, 3>& fallback);
  std::vector<std::string> Strings(const std::string& key);
  /** A nested object (or null if absent); its keys are the caller's to check. */
  const nlohmann::json* Object(const std::string& key);
  const nlohmann::json* Raw(const std::string& key);

  /**
   * Sets every parameter of `table` that this object has on `object` (keys
   * the object does not have keep the object's values); a value of the wrong
   * type or out of range throws SceneError naming the key, the value and
   * what the table allows.
   */
  void Apply(const vtkPlumeParameterTable& table, vtkObject* object);

  /** Throws SceneError naming the first key that no accessor asked for. */
  void RejectUnknown() const;

  const std::string& Where() const { return this->Location; }

private:
  const nlohmann::json* Get(const std::string& key);
  [[noreturn]] void Fail(const std::string& key, const std::string& expected, const nlohmann::json& got) const;

  const nlohmann::json& Json;
  std::string Location;
  std::set<std::string> Used;
};
}

#endif
