#include "vtkPlumeParameterTable.h"

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace
{
// Shortest text that reads back as the same double (%.17g would print 0.050000000000000003).
std::string Number(double v)
{
  if (std::isinf(v))
  {
    return v > 0 ? "inf" : "-inf";
  }
  for (int digits = 6; digits <= 17; ++digits)
  {
    std::ostringstream out;
    out << std::setprecision(digits) << v;
    // strtod, not stod: stod throws std::out_of_range on denormals (1e-310), found by fuzzing
    if (std::strtod(out.str().c_str(), nullptr) == v)
    {
      return out.str();
    }
  }
  std::ostringstream out;
  out << std::setprecision(17) << v;
  return out.str();
}

const char* ValueKindName(const vtkPlumeParameterTable::Value& value)
{
  switch (value.index())
  {
    case 0:
      return "a boolean";
    case 1:
      return "an integer";
    case 2:
      return "a number";
    case 3:
      return "a string";
    default:
      return "a list of 3 numbers";
  }
}
}

//------------------------------------------------------------------------------
vtkPlumeParameterTable::vtkPlumeParameterTable(const std::string& className, const std::string& sceneType)
  : ClassName(className)
  , SceneType(sceneType)
{
}

vtkPlumeParameterTable::Parameter& vtkPlumeParameterTable::Add(
  const std::string& key, const std::string& property, Kind kind, Value defaultValue)
{
  if (this->Find(key) || this->FindProperty(property))
  {
    throw std::logic_error(this->ClassName + ": parameter '" + key + "' (" + property + ") declared twice");
  }
  this->Parameters.emplace_back();
  Parameter& p = this->Parameters.back();
  p.Key = key;
  p.Property = property;
  p.Type = kind;
  p.Default = std::move(defaultValue);
  if (kind == Kind::Color)
  {
    p.Minimum = 0.0;
    p.Maximum = 1.0;
  }
  return p;
}

void vtkPlumeParameterTable::Include(
  const vtkPlumeParameterTable& part, std::function<vtkObject*(vtkObject*)> access, const std::string& propertyPrefix)
{
  for (const Parameter& q : part.GetParameters())
  {
    Parameter& p = this->Add(q.Key, propertyPrefix + q.Property, q.Type, q.Default);
    const Parameter copy = q;
    p = copy;
    p.Property = propertyPrefix + q.Property;
    if (q.Setter)
    {
      // the part's setter, then this object is modified (its pipeline must re-execute)
      p.Setter = [access, set = q.Setter, get = q.Getter](vtkObject* object, const Value& value) {
        vtkObject* target = access(object);
        const bool same = get && get(target) == value;
        set(target, value);
        if (!same)
        {
          object->Modified();
        }
      };
    }
    if (q.Getter)
    {
      p.Getter = [access, get = q.Getter](vtkObject* object) { return get(access(object)); };
    }
  }
}

vtkPlumeParameterTable::Parameter& vtkPlumeParameterTable::Boolean(
  const std::string& key, const std::string& property, bool defaultValue)
{
  return this->Add(key, property, Kind::Boolean, defaultValue);
}

vtkPlumeParameterTable::Parameter& vtkPlumeParameterTable::Integer(
  const std::string& key, const std::string& property, long long defaultValue)
{
  return this->Add(key, property, Kind::Integer, defaultValue);
}

vtkPlumeParameterTable::Parameter& vtkPlumeParameterTable::Real(
  const std::string& key, const std::string& property, double defaultValue)
{
  return this->Add(key, property, Kind::Real, defaultValue);
}

vtkPlumeParameterTable::Parameter& vtkPlumeParameterTable::Choice(
  const std::string& key, const std::string& property, const std::string& defaultKey)
{
  return this->Add(key, property, Kind::Choice, defaultKey);
}

vtkPlumeParameterTable::Parameter& vtkPlumeParameterTable::Text(
  const std::string& key, const std::string& property, const std::string& defaultValue)
{
  return this->Add(key, property, Kind::Text, defaultValue);
}

vtkPlumeParameterTable::Parameter& vtkPlumeParameterTable::Vector3(
  const std::string& key, const std::string& property, const std::array<double, 3>& defaultValue)
{
  return this->Add(key, property, Kind::Vector3, defaultValue);
}

vtkPlumeParameterTable::Parameter& vtkPlumeParameterTable::Color(
  const std::string& key, const std::string& property, const std::array<double, 3>& defaultValue)
{
  return this->Add(key, property, Kind::Color, defaultValue);
}

const vtkPlumeParameterTable::Parameter* vtkPlumeParameterTable::Find(const std::string& key) const
{
  for (const Parameter& p : this->Parameters)
  {
    if (p.Key == key)
    {
      return &p;
    }
  }
  return nullptr;
}

const vtkPlumeParameterTable::Parameter* vtkPlumeParameterTable::FindProperty(const std::string& property) const
{
  for (const Parameter& p : this->Parameters)
  {
    if (p.Property == property)
    {
      return &p;
    }
  }
  return nullptr;
}

void vtkPlumeParameterTable::ApplyDefaults(vtkObject* object) const
{
  for (const Parameter& p : this->Parameters)
  {
    if (p.Setter)
    {
      p.Set(object, p.Default);
    }
  }
}

//------------------------------------------------------------------------------
vtkPlumeParameterTable::Parameter& vtkPlumeParameterTable::Parameter::Between(double minimum, double maximum)
{
  this->Minimum = minimum;
  this->Maximum = maximum;
  return *this;
}

vtkPlumeParameterTable::Parameter& vtkPlumeParameterTable::Parameter::Units(const std::string& unit)
{
  this->Unit = unit;
  return *this;
}

vtkPlumeParameterTable::Parameter& vtkPlumeParameterTable::Parameter::Doc(const std::string& documentation)
{
  this->Documentation = documentation;
  return *this;
}

vtkPlumeParameterTable::Parameter& vtkPlumeParameterTable::Parameter::Panel(const std::string& group)
{
  this->Group = group;
  return *this;
}

vtkPlumeParameterTable::Parameter& vtkPlumeParameterTable::Parameter::Advanced(bool advanced)
{
  this->IsAdvanced = advanced;
  return *this;
}

vtkPlumeParameterTable::Parameter& vtkPlumeParameterTable::Parameter::Automatic(const std::string& meaning)
{
  if (this->Type != Kind::Real)
  {
    throw std::logic_error("'" + this->Key + "': only a real parameter can be automatic");
  }
  this->IsAutomatic = true;
  this->AutomaticMeaning = meaning;
  this->Default = std::numeric_limits<double>::quiet_NaN();
  return *this;
}

vtkPlumeParameterTable::Parameter& vtkPlumeParameterTable::Parameter::Choice(
  const std::string& key, int number, const std::string& doc)
{
  this->Options.push_back({ key, number, doc });
  return *this;
}

vtkPlumeParameterTable::Parameter& vtkPlumeParameterTable::Parameter::OnlyWith(
  const std::string& choiceKey, const std::vector<std::string>& options)
{
  this->OnlyWithKey = choiceKey;
  this->OnlyWithOptions = options;
  return *this;
}

const vtkPlumeParameterTable::Option* vtkPlumeParameterTable::Parameter::FindOption(const std::string& key) const
{
  for (const Option& o : this->Options)
  {
    if (o.Key == key)
    {
      return &o;
    }
  }
  return nullptr;
}

const vtkPlumeParameterTable::Option* vtkPlumeParameterTable::Parameter::FindOption(int number) const
{
  for (const Option& o : this->Options)
  {
    if (o.Number == number)
    {
      return &o;
    }
  }
  return nullptr;
}

std::string vtkPlumeParameterTable::Parameter::Check(const Value& value) const
{
  auto range = [this]() {
    std::ostringstream out;
    out << "in [" << Number(this->Minimum) << ", " << Number(this->Maximum) << "]";
    return out.str();
  };
  auto inRange = [this](double v) { return std::isfinite(v) && v >= this->Minimum && v <= this->Maximum; };
  auto got = [&value]() { return std::string(", got ") + ValueKindName(value) + " " + Format(value); };
  switch (this->Type)
  {
    case Kind::Boolean:
      return std::holds_alternative<bool>(value) ? "" : "must be true or false" + got();
    case Kind::Integer:
      if (!std::holds_alternative<long long>(value))
      {
        return "must be an integer " + range() + got();
      }
      return inRange(static_cast<double>(std::get<long long>(value))) ? "" : "must be an integer " + range() + got();
    case Kind::Real:
    {
      double v = 0;
      if (std::holds_alternative<double>(value))
      {
        v = std::get<double>(value);
      }
      else if (std::holds_alternative<long long>(value))
      {
        v = static_cast<double>(std::get<long long>(value));
      }
      else
      {
        return "must be a finite number " + range() + got();
      }
      if (this->IsAutomatic && std::isnan(v))
      {
        return ""; // unset: the class chooses
      }
      return inRange(v) ? "" : "must be a finite number " + range() + got();
    }
    case Kind::Choice:
    {
      std::string names;
      for (const Option& o : this->Options)
      {
        names += (names.empty() ? "\"" : ", \"") + o.Key + "\"";
      }
      if (!std::holds_alternative<std::string>(value) || !this->FindOption(std::get<std::string>(value)))
      {
        return "must be one of " + names + got();
      }
      return "";
    }
    case Kind::Text:
      if (!std::holds_alternative<std::string>(value))
      {
        return "must be a string" + got();
      }
      return std::get<std::string>(value).find('\0') == std::string::npos ? ""
                                                                          : "must not contain a NUL character";
    case Kind::Vector3:
    case Kind::Color:
    {
      const std::string what = this->Type == Kind::Color ? "an RGB colour: 3 numbers " : "3 finite numbers ";
      if (!std::holds_alternative<std::array<double, 3>>(value))
      {
        return "must be " + what + range() + got();
      }
      for (double v : std::get<std::array<double, 3>>(value))
      {
        if (!inRange(v))
        {
          return "must be " + what + range() + got();
        }
      }
      return "";
    }
  }
  return "has an unknown type";
}

void vtkPlumeParameterTable::Parameter::Set(vtkObject* object, const Value& value) const
{
  const std::string problem = this->Check(value);
  if (!problem.empty())
  {
    throw std::invalid_argument("'" + this->Key + "' " + problem);
  }
  if (!this->Setter)
  {
    throw std::logic_error("'" + this->Key + "' is not bound to a setter");
  }
  if (this->Type == Kind::Choice)
  {
    this->Setter(object, static_cast<long long>(this->FindOption(std::get<std::string>(value))->Number));
  }
  else if (this->Type == Kind::Real && std::holds_alternative<long long>(value))
  {
    this->Setter(object, static_cast<double>(std::get<long long>(value)));
  }
  else
  {
    this->Setter(object, value);
  }
}

vtkPlumeParameterTable::Value vtkPlumeParameterTable::Parameter::Get(vtkObject* object) const
{
  if (!this->Getter)
  {
    throw std::logic_error("'" + this->Key + "' is not bound to a getter");
  }
  Value v = this->Getter(object);
  if (this->Type == Kind::Choice && std::holds_alternative<long long>(v))
  {
    const Option* o = this->FindOption(static_cast<int>(std::get<long long>(v)));
    return o ? Value(o->Key) : Value(std::to_string(std::get<long long>(v)));
  }
  if (this->Type == Kind::Boolean && std::holds_alternative<long long>(v))
  {
    return std::get<long long>(v) != 0;
  }
  return v;
}

//------------------------------------------------------------------------------
std::string vtkPlumeParameterTable::Format(const Value& value)
{
  switch (value.index())
  {
    case 0:
      return std::get<bool>(value) ? "true" : "false";
    case 1:
      return std::to_string(std::get<long long>(value));
    case 2:
      return Number(std::get<double>(value));
    case 3:
      return "\"" + std::get<std::string>(value) + "\"";
    default:
    {
      const auto& v = std::get<std::array<double, 3>>(value);
      return "[" + Number(v[0]) + ", " + Number(v[1]) + ", " + Number(v[2]) + "]";
    }
  }
}

const char* vtkPlumeParameterTable::KindName(Kind kind)
{
  switch (kind)
  {
    case Kind::Boolean:
      return "boolean";
    case Kind::Integer:
      return "integer";
    case Kind::Real:
      return "number";
    case Kind::Choice:
      return "choice";
    case Kind::Text:
      return "string";
    case Kind::Vector3:
      return "3 numbers";
    case Kind::Color:
      return "RGB colour";
  }
  return "?";
}

void vtkPlumeParameterTable::WriteMarkdown(std::ostream& os) const
{
  os << "| key | type | default | range | description |\n";
  os << "|---|---|---|---|---|\n";
  for (const Parameter& p : this->Parameters)
  {
    std::string range;
    if (p.Type == Kind::Choice)
    {
      for (const Option& o : p.Options)
      {
        range += (range.empty() ? "" : ", ") + ("`\"" + o.Key + "\"`");
      }
    }
    else if (p.Type == Kind::Integer || p.Type == Kind::Real || p.Type == Kind::Vector3)
    {
      if (std::isfinite(p.Minimum) || std::isfinite(p.Maximum))
      {
        range = Number(p.Minimum) + " … " + Number(p.Maximum);
      }
    }
    std::string doc = p.Documentation;
    if (!p.Unit.empty())
    {
      doc += " (" + p.Unit + ")";
    }
    if (p.Type == Kind::Choice)
    {
      for (const Option& o : p.Options)
      {
        doc += " `\"" + o.Key + "\"`: " + o.Doc;
      }
    }
    const std::string def =
      p.IsAutomatic ? "automatic (" + p.AutomaticMeaning + ")" : "`" + Format(p.Default) + "`";
    os << "| `" << p.Key << "` | " << KindName(p.Type) << " | " << def << " | " << range << " | " << doc
       << " |\n";
  }
}
