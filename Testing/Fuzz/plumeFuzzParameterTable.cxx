// libFuzzer target: vtkPlumeParameterTable. The bytes choose a parameter of a
// table with every kind (boolean, integer, real, choice, text, 3-vector,
// colour) and a value of any type; Check() must accept exactly the values
// Set() can store: after a successful Check, Set then Get must give the
// value back (choices by name), inside the declared range. A crash, a
// sanitizer report or a broken round trip is a finding.
#include "vtkPlumeParameterTable.h"

#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkSetGet.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

namespace
{
class FuzzSample : public vtkObject
{
public:
  static FuzzSample* New();
  vtkTypeMacro(FuzzSample, vtkObject);
  vtkSetMacro(On, bool);
  vtkGetMacro(On, bool);
  vtkSetMacro(Count, int);
  vtkGetMacro(Count, int);
  vtkSetMacro(Big, vtkIdType);
  vtkGetMacro(Big, vtkIdType);
  vtkSetMacro(Scale, double);
  vtkGetMacro(Scale, double);
  vtkSetMacro(Mode, int);
  vtkGetMacro(Mode, int);
  vtkSetStdStringFromCharMacro(Name);
  vtkGetCharFromStdStringMacro(Name);
  vtkSetVector3Macro(Axis, double);
  vtkGetVector3Macro(Axis, double);
  vtkSetVector3Macro(Tint, double);
  vtkGetVector3Macro(Tint, double);

  bool On = false;
  int Count = 1;
  vtkIdType Big = 0;
  double Scale = 1;
  int Mode = 0;
  std::string Name;
  double Axis[3] = { 0, 0, 1 };
  double Tint[3] = { 1, 1, 1 };
};
vtkStandardNewMacro(FuzzSample);

const vtkPlumeParameterTable& Table()
{
  static const vtkPlumeParameterTable table = [] {
    using T = FuzzSample;
    vtkPlumeParameterTable t("FuzzSample", "fuzz");
    t.Boolean("on", "On", false).Doc("a flag").Bind(&T::SetOn, &T::GetOn);
    t.Integer("count", "Count", 1).Between(1, 32).Doc("an int").Bind(&T::SetCount, &T::GetCount);
    t.Integer("big", "Big", 0).Between(0, 1e15).Doc("a wide int").Bind(&T::SetBig, &T::GetBig);
    t.Real("scale", "Scale", 1.0).Between(1e-6, 1e6).Doc("a real").Bind(&T::SetScale, &T::GetScale);
    t.Choice("mode", "Mode", "a").Choice("a", 0, "first").Choice("b", 7, "second").Doc("a choice")
      .Bind(&T::SetMode, &T::GetMode);
    t.Text("name", "Name", "").Doc("a name").Bind(&T::SetName, &T::GetName);
    t.Vector3("axis", "Axis", { 0, 0, 1 }).Between(-1e3, 1e3).Doc("a vector").Bind(&T::SetAxis, &T::GetAxis);
    t.Color("tint", "Tint", { 1, 1, 1 }).Doc("a colour").Bind(&T::SetTint, &T::GetTint);
    return t;
  }();
  return table;
}

double Real(const uint8_t*& data, size_t& size)
{
  double v = 0;
  if (size >= sizeof(double))
  {
    std::memcpy(&v, data, sizeof(double));
    data += sizeof(double);
    size -= sizeof(double);
  }
  return v;
}
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  if (size < 2)
  {
    return 0;
  }
  const auto& params = Table().GetParameters();
  const vtkPlumeParameterTable::Parameter& p = params[data[0] % params.size()];
  const int type = data[1] % 5;
  data += 2;
  size -= 2;
  vtkPlumeParameterTable::Value value;
  switch (type)
  {
    case 0: value = size > 0 && (data[0] & 1); break;
    case 1:
    {
      long long v = 0;
      std::memcpy(&v, data, std::min(size, sizeof(v)));
      value = v;
      break;
    }
    case 2: value = Real(data, size); break;
    case 3: value = std::string(reinterpret_cast<const char*>(data), size); break;
    default:
    {
      std::array<double, 3> v;
      for (double& c : v)
      {
        c = Real(data, size);
      }
      value = v;
    }
  }
  vtkNew<FuzzSample> object;
  Table().ApplyDefaults(object);
  const std::string problem = p.Check(value);
  (void)vtkPlumeParameterTable::Format(value);
  if (!problem.empty())
  {
    if (problem.compare(0, 5, "must ") != 0)
    {
      std::abort(); // every refusal says what the value must be (the caller adds the key)
    }
    return 0;
  }
  p.Set(object, value);
  const vtkPlumeParameterTable::Value back = p.Get(object);
  if (!p.Check(back).empty())
  {
    std::abort(); // what was accepted and stored must still be valid
  }
  if (value.index() == back.index() && value != back && !(std::holds_alternative<double>(value) &&
        std::isnan(std::get<double>(value))))
  {
    std::abort(); // same type in, same value out
  }
  return 0;
}
