#include "plumeParameters.h"

#include "plumeSceneError.h"

#include "vtkPlumeParameterTable.h"

#include <cmath>
#include <limits>
#include <sstream>

namespace plume
{
namespace
{
// Scene numbers end up in 32-bit floats (shader uniforms, float arrays, the projection):
// one beyond float range becomes Inf there, a denormal becomes 0 (then 1/x is Inf), and
// the frame fills with NaN. Refused here, where the message can name the key.
bool FloatRepresentable(double x)
{
  const double a = std::fabs(x);
  return a == 0 || (a >= std::numeric_limits<float>::min() && a <= std::numeric_limits<float>::max());
}
const char* const FloatRange = " representable as a 32-bit float (0, or magnitude 1.2e-38 to 3.4e+38)";
}

Parameters::Parameters(const nlohmann::json& object, std::string where)
  : Json(object)
  , Location(std::move(where))
{
  if (!object.is_object())
  {
    throw SceneError(this->Location + ": expected a JSON object, got " + object.dump());
  }
}

bool Parameters::Has(const std::string& key) const
{
  return this->Json.contains(key);
}

const nlohmann::json* Parameters::Get(const std::string& key)
{
  this->Used.insert(key);
  auto it = this->Json.find(key);
  return it == this->Json.end() ? nullptr : &*it;
}

void Parameters::Fail(const std::string& key, const std::string& expected, const nlohmann::json& got) const
{
  std::string shown = got.dump();
  if (shown.size() > 80)
  {
    shown = shown.substr(0, 77) + "...";
  }
  throw SceneError(this->Location + ": parameter '" + key + "' must be " + expected + ", got " + shown);
}

void Parameters::Apply(const vtkPlumeParameterTable& table, vtkObject* object)
{
  using Kind = vtkPlumeParameterTable::Kind;
  for (const vtkPlumeParameterTable::Parameter& parameter : table.GetParameters())
  {
    const nlohmann::json* json = this->Get(parameter.Key);
    if (!json)
    {
      continue;
    }
    // JSON -> the table's value; Check() then says what is wrong with it
    vtkPlumeParameterTable::Value value;
    if (json->is_boolean())
    {
      value = json->get<bool>();
    }
    else if (json->is_number_integer() && (parameter.Type == Kind::Integer || parameter.Type == Kind::Real))
    {
      value = parameter.Type == Kind::Integer ? vtkPlumeParameterTable::Value(json->get<long long>())
                                              : vtkPlumeParameterTable::Value(json->get<double>());
    }
    else if (json->is_number() && (parameter.Type == Kind::Vector3 || parameter.Type == Kind::Color))
    {
      const double x = json->get<double>(); // one number: grey, or the same on every axis
      value = std::array<double, 3>{ x, x, x };
    }
    else if (json->is_number())
    {
      value = json->get<double>();
    }
    else if (json->is_string())
    {
      value = json->get<std::string>();
    }
    else if (json->is_array() && json->size() == 3 && (*json)[0].is_number() && (*json)[1].is_number() &&
      (*json)[2].is_number())
    {
      value = std::array<double, 3>{ (*json)[0].get<double>(), (*json)[1].get<double>(), (*json)[2].get<double>() };
    }
    else
    {
      this->Fail(parameter.Key, std::string("of type ") + vtkPlumeParameterTable::KindName(parameter.Type), *json);
    }
    std::string problem = parameter.Check(value);
    // in range for the table, and representable where it ends up (float uniforms)
    if (problem.empty() && std::holds_alternative<double>(value) && !FloatRepresentable(std::get<double>(value)))
    {
      problem = std::string("must be a number") + FloatRange;
    }
    if (problem.empty() && std::holds_alternative<std::array<double, 3>>(value))
    {
      for (double x : std::get<std::array<double, 3>>(value))
      {
        if (!FloatRepresentable(x))
        {
          problem = std::string("must be 3 numbers") + FloatRange;
        }
      }
    }
    if (!problem.empty())
    {
      std::string shown = json->dump();
      if (shown.size() > 80)
      {
        shown = shown.substr(0, 77) + "...";
      }
      throw SceneError(this->Location + ": parameter '" + parameter.Key + "' " + problem +
        (problem.find(", got ") == std::string::npos ? ", got " + shown : std::string()));
    }
    parameter.Set(object, value);
  }
}

double Parameters::Number(const std::string& key, double fallback, double min, double max)
{
  const nlohmann::json* value = this->Get(key);
  if (!value)
  {
    return fallback;
  }
  if (!value->is_number())
  {
    this->Fail(key, "a number", *value);
  }
  const double x = value->get<double>();
  if (!std::isfinite(x) || x < min || x > max)
  {
    std::ostringstream range;
    range << "a finite number in [" << min << ", " << max << "]";
    this->Fail(key, range.str(), *value);
  }
  if (!FloatRepresentable(x))
  {
    this->Fail(key, std::string("a number") + FloatRange, *value);
  }
  return x;
}

int Parameters::Integer(const std::string& key, int fallback, int min, int max)
{
  const nlohmann::json* value = this->Get(key);
  if (!value)
  {
    return fallback;
  }
  std::ostringstream range;
  range << "an integer in [" << min << ", " << max << "]";
  if (!value->is_number_integer())
  {
    this->Fail(key, range.str(), *value);
  }
  const long long x = value->get<long long>();
  if (x < min || x > max)
  {
    this->Fail(key, range.str(), *value);
  }
  return static_cast<int>(x);
}

bool Parameters::Boolean(const std::string& key, bool fallback)
{
  const nlohmann::json* value = this->Get(key);
  if (!value)
  {
    return fallback;
  }
  if (!value->is_boolean())
  {
    this->Fail(key, "true or false", *value);
  }
  return value->get<bool>();
}

std::string Parameters::String(const std::string& key, const std::string& fallback)
{
  const nlohmann::json* value = this->Get(key);
  if (!value)
  {
    return fallback;
  }
  if (!value->is_string())
  {
    this->Fail(key, "a string", *value);
  }
  return value->get<std::string>();
}

std::string Parameters::Choice(
  const std::string& key, const std::string& fallback, const std::vector<std::string>& choices)
{
  const std::string s = this->String(key, fallback);
  for (const auto& c : choices)
  {
    if (c == s)
    {
      return s;
    }
  }
  std::string list;
  for (const auto& c : choices)
  {
    list += (list.empty() ? "" : ", ") + c;
  }
  this->Fail(key, "one of " + list, *this->Json.find(key));
}

template <size_t N>
std::array<double, N> Parameters::Vector(const std::string& key, const std::array<double, N>& fallback)
{
  const nlohmann::json* value = this->Get(key);
  if (!value)
  {
    return fallback;
  }
  const std::string expected = "a list of " + std::to_string(N) + " finite numbers";
  if (!value->is_array() || value->size() != N)
  {
    this->Fail(key, expected, *value);
  }
  std::array<double, N> out;
  for (size_t i = 0; i < N; ++i)
  {
    if (!(*value)[i].is_number() || !std::isfinite((*value)[i].template get<double>()))
    {
      this->Fail(key, expected, *value);
    }
    out[i] = (*value)[i].template get<double>();
    if (!FloatRepresentable(out[i]))
    {
      this->Fail(key, "a list of " + std::to_string(N) + " numbers" + FloatRange, *value);
    }
  }
  return out;
}

template std::array<double, 2> Parameters::Vector<2>(const std::string&, const std::array<double, 2>&);
template std::array<double, 3> Parameters::Vector<3>(const std::string&, const std::array<double, 3>&);
template std::array<double, 6> Parameters::Vector<6>(const std::string&, const std::array<double, 6>&);

std::array<double, 3> Parameters::Color(const std::string& key, const std::array<double, 3>& fallback)
{
  const std::array<double, 3> c = this->Vector<3>(key, fallback);
  for (double v : c)
  {
    if (v < 0 || v > 1)
    {
      this->Fail(key, "an RGB colour: 3 numbers in [0, 1]", *this->Json.find(key));
    }
  }
  return c;
}

std::vector<std::string> Parameters::Strings(const std::string& key)
{
  std::vector<std::string> out;
  const nlohmann::json* value = this->Get(key);
  if (!value)
  {
    return out;
  }
  if (value->is_string())
  {
    out.push_back(value->get<std::string>());
    return out;
  }
  if (!value->is_array())
  {
    this->Fail(key, "a string or a list of strings", *value);
  }
  for (const auto& item : *value)
  {
    if (!item.is_string())
    {
      this->Fail(key, "a string or a list of strings", *value);
    }
    out.push_back(item.get<std::string>());
  }
  return out;
}

const nlohmann::json* Parameters::Object(const std::string& key)
{
  const nlohmann::json* value = this->Get(key);
  if (value && !value->is_object())
  {
    this->Fail(key, "an object", *value);
  }
  return value;
}

const nlohmann::json* Parameters::Raw(const std::string& key)
{
  return this->Get(key);
}

void Parameters::RejectUnknown() const
{
  for (auto it = this->Json.begin(); it != this->Json.end(); ++it)
  {
    if (!this->Used.count(it.key()))
    {
      std::string known;
      for (const auto& k : this->Used)
      {
        known += (known.empty() ? "" : ", ") + k;
      }
      throw SceneError(this->Location + ": unknown parameter '" + it.key() + "' (known: " + known + ")");
    }
  }
}

}
