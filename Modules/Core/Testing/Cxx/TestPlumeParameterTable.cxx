// vtkPlumeParameterTable: defaults reach the object, values are type- and
// range-checked with messages naming the key, choices map names to numbers,
// every binding signature round-trips, and the markdown lists every key.
#include "vtkPlumeParameterTable.h"

#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkSetGet.h"

#include <cmath>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace
{
int tableFailures = 0;
#define CHECK(cond)                                                                                 \
  do                                                                                                \
  {                                                                                                 \
    if (!(cond))                                                                                    \
    {                                                                                               \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #cond "\n";                    \
      ++tableFailures;                                                                                   \
    }                                                                                               \
  } while (false)

class Sample : public vtkObject
{
public:
  static Sample* New();
  vtkTypeMacro(Sample, vtkObject);
  static const vtkPlumeParameterTable& GetParameterTable();

  vtkSetMacro(On, bool);
  vtkGetMacro(On, bool);
  vtkSetClampMacro(Count, int, 1, 32);
  vtkGetMacro(Count, int);
  vtkSetClampMacro(Big, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(Big, vtkIdType);
  vtkSetClampMacro(Width, double, 0.0, 10.0);
  vtkGetMacro(Width, double);
  vtkSetClampMacro(Mode, int, 0, 2);
  vtkGetMacro(Mode, int);
  vtkSetStdStringFromCharMacro(ArrayName);
  vtkGetCharFromStdStringMacro(ArrayName);
  vtkSetVector3Macro(Tint, double);
  vtkGetVector3Macro(Tint, double);

protected:
  Sample() { GetParameterTable().ApplyDefaults(this); }
  bool On = false;
  int Count = 0;
  vtkIdType Big = 0;
  double Width = 0;
  int Mode = 0;
  std::string ArrayName;
  double Tint[3] = { 0, 0, 0 };
};
vtkStandardNewMacro(Sample);

const vtkPlumeParameterTable& Sample::GetParameterTable()
{
  static const vtkPlumeParameterTable table = [] {
    using T = Sample;
    vtkPlumeParameterTable t("Sample", "sample");
    t.Boolean("on", "On", true).Doc("Switch.").Bind(&T::SetOn, &T::GetOn);
    t.Integer("count", "Count", 8).Between(1, 32).Doc("Count.").Bind(&T::SetCount, &T::GetCount);
    t.Integer("big", "Big", 16384).Between(0, 1e18).Doc("Big.").Bind(&T::SetBig, &T::GetBig);
    t.Real("width", "Width", 0.05).Between(0, 10).Units("model units").Doc("Width.").Bind(&T::SetWidth, &T::GetWidth);
    t.Choice("mode", "Mode", "analytic")
      .Choice("grid", 0, "a grid")
      .Choice("analytic", 1, "closed form")
      .Choice("mixed", 2, "both")
      .Doc("Quadrature.")
      .Bind(&T::SetMode, &T::GetMode);
    t.Text("array", "ArrayName", "").Doc("Array.").Bind(&T::SetArrayName, &T::GetArrayName);
    t.Color("tint", "Tint", { 0.25, 0.5, 1.0 }).Doc("Tint.").Bind(&T::SetTint, &T::GetTint);
    return t;
  }();
  return table;
}
}

int TestPlumeParameterTable(int, char*[])
{
  // denormals format without throwing (std::stod threw out_of_range; a fuzzer finding)
  CHECK(vtkPlumeParameterTable::Format(4.9e-324) == "4.94066e-324");
  CHECK(vtkPlumeParameterTable::Format(std::array<double, 3>{ 1e-310, 0, 1 }).find("1e-310") != std::string::npos);
  const vtkPlumeParameterTable& table = Sample::GetParameterTable();
  vtkNew<Sample> s;
  // defaults reached the object through the bindings
  CHECK(s->GetOn() == true);
  CHECK(s->GetCount() == 8);
  CHECK(s->GetBig() == 16384);
  CHECK(s->GetWidth() == 0.05);
  CHECK(s->GetMode() == 1);
  CHECK(std::string(s->GetArrayName()).empty());
  CHECK(s->GetTint()[0] == 0.25 && s->GetTint()[1] == 0.5 && s->GetTint()[2] == 1.0);
  // and read back in the table's terms
  for (const auto& p : table.GetParameters())
  {
    CHECK(p.Get(s) == p.Default);
  }

  // set through the table
  table.Find("mode")->Set(s, std::string("grid"));
  CHECK(s->GetMode() == 0);
  CHECK(std::get<std::string>(table.Find("mode")->Get(s)) == "grid");
  table.Find("width")->Set(s, 2LL); // an integer is a valid number
  CHECK(s->GetWidth() == 2.0);
  table.Find("tint")->Set(s, std::array<double, 3>{ 1, 0, 0 });
  CHECK(s->GetTint()[0] == 1 && s->GetTint()[1] == 0);
  table.Find("array")->Set(s, std::string("U"));
  CHECK(std::string(s->GetArrayName()) == "U");
  table.Find("on")->Set(s, false);
  CHECK(!s->GetOn());

  // checks: type, range, non-finite, unknown choice; the message names the range or choices
  CHECK(table.Find("count")->Check(0LL).find("in [1, 32]") != std::string::npos);
  CHECK(table.Find("count")->Check(2.5).find("integer") != std::string::npos);
  CHECK(table.Find("width")->Check(std::nan("")).find("finite") != std::string::npos);
  CHECK(table.Find("width")->Check(11.0).find("in [0, 10]") != std::string::npos);
  CHECK(table.Find("width")->Check(std::string("x")).find("got a string") != std::string::npos);
  CHECK(table.Find("mode")->Check(std::string("exact")).find("\"grid\", \"analytic\", \"mixed\"") != std::string::npos);
  CHECK(table.Find("tint")->Check(std::array<double, 3>{ 0, 2, 0 }).find("RGB") != std::string::npos);
  CHECK(table.Find("on")->Check(1LL).find("true or false") != std::string::npos);
  bool threw = false;
  try
  {
    table.Find("width")->Set(s, -1.0);
  }
  catch (const std::invalid_argument& e)
  {
    threw = std::string(e.what()).find("'width'") != std::string::npos;
  }
  CHECK(threw);
  CHECK(s->GetWidth() == 2.0); // unchanged by the refused value

  // duplicate declarations are a programming error
  threw = false;
  try
  {
    vtkPlumeParameterTable t("X", "x");
    t.Real("a", "A", 1);
    t.Real("a", "B", 1);
  }
  catch (const std::logic_error&)
  {
    threw = true;
  }
  CHECK(threw);

  // formatting and markdown
  CHECK(vtkPlumeParameterTable::Format(0.05) == "0.05");
  CHECK(vtkPlumeParameterTable::Format(1.0 / 3.0) == "0.3333333333333333");
  std::ostringstream md;
  table.WriteMarkdown(md);
  for (const auto& p : table.GetParameters())
  {
    CHECK(md.str().find("| `" + p.Key + "` |") != std::string::npos);
  }
  CHECK(md.str().find("(model units)") != std::string::npos);
  if (tableFailures)
  {
    std::cerr << tableFailures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
