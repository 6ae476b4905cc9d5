/**
 * @class   vtkPlumeParameterTable
 * @brief   the one declaration of a Plume class's user parameters
 *
 * Every Plume class with parameters a user sets (mappers, filters, sources,
 * passes) declares them once, in a static table returned by its
 * `GetParameterTable()`: for each parameter the scene key, the VTK property
 * (Set/Get method and ParaView property name), its type, default, range,
 * unit, documentation, ParaView panel group and whether it is advanced. From
 * that one declaration:
 *  - the class takes its defaults (ApplyDefaults(this) in the constructor),
 *  - the `plume` scene reader sets the parameters of a scene object (Check,
 *    then Set), with one error naming the key, the value and the range,
 *  - Documentation/SceneFormat.md's parameter tables are generated
 *    (`plume params --markdown`) and a test checks the document holds them,
 *  - the ParaView plugin's server-manager properties are generated,
 *  - a test checks the class's C++ setters against the table (its getters
 *    return the defaults after construction; setters clamp to the range).
 *
 * Declaring a table (in the class's .cxx):
 * @code
 *   const vtkPlumeParameterTable& vtkPlumeSheetMapper::GetParameterTable()
 *   {
 *     static const vtkPlumeParameterTable table = [] {
 *       using T = vtkPlumeSheetMapper;
 *       vtkPlumeParameterTable t("vtkPlumeSheetMapper", "sheet");
 *       t.Real("blur", "BlurRadius", 0.05)
 *         .Between(0.0, 1e30).Units("model units").Panel("Smoke")
 *         .Doc("Blurring radius sigma_b in the surface where no array is used.")
 *         .Bind(&T::SetBlurRadius, &T::GetBlurRadius);
 *       return t;
 *     }();
 *     return table;
 *   }
 * @endcode
 * A real parameter may default to "automatic": `.Automatic("the middle of
 * the colour map's range")` makes its default NaN, which the class reads as
 * "not set, choose for me". Check accepts NaN for it (the unset value; scenes
 * cannot write NaN, so a scene either gives a finite value or leaves the key
 * out), the markdown shows "automatic (...)" as the default and the ParaView
 * property takes its initial value from the C++ object (default_values="none").
 *
 * Binding takes the class's own Set/Get methods (vtkSetMacro and friends):
 * booleans, integers (any integral type), reals, choices (an int setter; the
 * scene names each value), text (`const char*`, e.g. array names) and 3-vectors
 * or colours (`const double[3]` setter, `double*` getter).
 */
#ifndef vtkPlumeParameterTable_h
#define vtkPlumeParameterTable_h

#include "PlumeCoreModule.h" // For export macro
#include "vtkObject.h"       // For vtkObject (bindings)
#include "vtkWrappingHints.h" // For VTK_WRAPEXCLUDE

#include <array>       // For std::array
#include <deque>       // For std::deque
#include <functional>  // For std::function
#include <limits>      // For std::numeric_limits
#include <ostream>     // For std::ostream
#include <string>      // For std::string
#include <type_traits> // For std::is_integral
#include <variant>     // For std::variant
#include <vector>      // For std::vector

class PLUMECORE_EXPORT VTK_WRAPEXCLUDE vtkPlumeParameterTable
{
public:
  enum class Kind
  {
    Boolean,
    Integer,
    Real,
    Choice, ///< an int property whose values have names in scenes
    Text,   ///< a string (array name, file name)
    Vector3,
    Color ///< RGB, each in [0, 1]
  };

  /** A parameter value: bool, integer, real, text (also a choice's name) or 3-vector. */
  using Value = std::variant<bool, long long, double, std::string, std::array<double, 3>>;

  /** One named value of a choice. */
  struct Option
  {
    std::string Key;  ///< the name in scenes, e.g. "analytic"
    int Number;       ///< the value the C++ setter takes
    std::string Doc;  ///< what it means
  };

  class PLUMECORE_EXPORT Parameter
  {
  public:
    std::string Key;      ///< scene key (snake_case)
    std::string Property; ///< VTK property: Set<Property>/Get<Property>; the ParaView property name
    Kind Type = Kind::Real;
    Value Default;
    double Minimum = -std::numeric_limits<double>::infinity(); ///< numbers and vector components
    double Maximum = std::numeric_limits<double>::infinity();
    std::vector<Option> Options; ///< choices
    std::string Unit;            ///< e.g. "voxels", "model units"; "" for none
    std::string Documentation;   ///< one or two sentences
    std::string Group;           ///< ParaView panel group ("" = the class's main group)
    bool IsAdvanced = false;     ///< behind ParaView's gear button
    bool IsAutomatic = false;    ///< reals: the default is NaN, "automatic" (see Automatic())
    std::string AutomaticMeaning; ///< what "automatic" chooses, e.g. "the middle of the colour map's range"
    std::string OnlyWithKey;              ///< the choice this parameter depends on ("" = none, see OnlyWith())
    std::vector<std::string> OnlyWithOptions; ///< the options of that choice under which it applies
    std::function<void(vtkObject*, const Value&)> Setter;
    std::function<Value(vtkObject*)> Getter;

    ///@{
    /** Fluent declaration. */
    Parameter& Between(double minimum, double maximum);
    Parameter& Units(const std::string& unit);
    Parameter& Doc(const std::string& documentation);
    Parameter& Panel(const std::string& group);
    Parameter& Advanced(bool advanced = true);
    /**
     * Reals only: the default is "automatic" (NaN, chosen by the class at run
     * time as `meaning` says); NaN is then a valid value (the unset one).
     */
    Parameter& Automatic(const std::string& meaning);
    /** Adds a named value to a choice. */
    Parameter& Choice(const std::string& key, int number, const std::string& doc);
    /**
     * The parameter matters only while the choice `choiceKey` (a scene key
     * of the same table) is one of `options`, e.g. a fixed scale only with
     * scale_mode "fixed": ParaView's panel hides it otherwise.
     */
    Parameter& OnlyWith(const std::string& choiceKey, const std::vector<std::string>& options);
    ///@}

    /** Binds the class's Set/Get methods (see the class documentation for the supported signatures). */
    template <class C, class S, class G>
    Parameter& Bind(void (C::*set)(S), G (C::*get)());

    /** "" if `value` has this parameter's type and lies in its range, else why not. */
    std::string Check(const Value& value) const;
    /** Sets `object`'s property to `value` (checked first: an invalid value throws std::invalid_argument). */
    void Set(vtkObject* object, const Value& value) const;
    /** `object`'s current value, in the table's terms (a choice's name, a boolean). */
    Value Get(vtkObject* object) const;
    /** The option named `key` (choices), or nullptr. */
    const Option* FindOption(const std::string& key) const;
    /** The option whose number is `number` (choices), or nullptr. */
    const Option* FindOption(int number) const;
  };

  /** `className`: the C++ class; `sceneType`: its name in scenes (e.g. "sheet"), "" if none. */
  vtkPlumeParameterTable(const std::string& className, const std::string& sceneType);

  ///@{
  /** Declare a parameter (then chain Between, Units, Doc, Panel, Advanced, Choice, Bind). */
  Parameter& Boolean(const std::string& key, const std::string& property, bool defaultValue);
  Parameter& Integer(const std::string& key, const std::string& property, long long defaultValue);
  Parameter& Real(const std::string& key, const std::string& property, double defaultValue);
  Parameter& Choice(const std::string& key, const std::string& property, const std::string& defaultKey);
  Parameter& Text(const std::string& key, const std::string& property, const std::string& defaultValue);
  Parameter& Vector3(const std::string& key, const std::string& property, const std::array<double, 3>& defaultValue);
  Parameter& Color(const std::string& key, const std::string& property, const std::array<double, 3>& defaultValue);
  ///@}

  /**
   * Declares every parameter of `part`'s table as a parameter of this class
   * too, reached through `access` (the class's getter of the part, e.g. its
   * pressure solver): the part's declaration stays the only one. Properties
   * get `propertyPrefix` (e.g. "Pressure" + "Tolerance"), keys stay the part's.
   * Setting one through this table marks the object (not only the part) modified.
   */
  void Include(const vtkPlumeParameterTable& part, std::function<vtkObject*(vtkObject*)> access,
    const std::string& propertyPrefix);

  const std::string& GetClassName() const { return this->ClassName; }
  const std::string& GetSceneType() const { return this->SceneType; }
  const std::deque<Parameter>& GetParameters() const { return this->Parameters; }
  /** The parameter with scene key `key`, or nullptr. */
  const Parameter* Find(const std::string& key) const;
  /** The parameter whose property is `property`, or nullptr. */
  const Parameter* FindProperty(const std::string& property) const;

  /** Sets every bound parameter of `object` to its default (call it in the constructor). */
  void ApplyDefaults(vtkObject* object) const;

  /** Markdown table (key | type | default | range | description) of the scene parameters. */
  void WriteMarkdown(std::ostream& os) const;

  /** A value as scenes write it (JSON-like): true, 3, 0.05, "grid", [0, 0, 1]. */
  static std::string Format(const Value& value);
  /** The kind's name in messages and documentation: "boolean", "integer", "number", ... */
  static const char* KindName(Kind kind);

private:
  Parameter& Add(const std::string& key, const std::string& property, Kind kind, Value defaultValue);

  std::string ClassName;
  std::string SceneType;
  std::deque<Parameter> Parameters; // deque: references stay valid while declaring
};

//------------------------------------------------------------------------------
template <class C, class S, class G>
vtkPlumeParameterTable::Parameter& vtkPlumeParameterTable::Parameter::Bind(void (C::*set)(S), G (C::*get)())
{
  // Choices and booleans reach integral setters as integers: Set() has
  // already turned a choice's name into its number.
  this->Setter = [set](vtkObject* object, const Value& value) {
    C* self = static_cast<C*>(object);
    using Arg = std::decay_t<S>;
    if constexpr (std::is_same_v<Arg, bool>)
    {
      (self->*set)(std::get<bool>(value));
    }
    else if constexpr (std::is_integral_v<Arg>)
    {
      (self->*set)(static_cast<Arg>(std::holds_alternative<bool>(value) ? std::get<bool>(value)
                                                                      : std::get<long long>(value)));
    }
    else if constexpr (std::is_floating_point_v<Arg>)
    {
      (self->*set)(static_cast<Arg>(std::get<double>(value)));
    }
    else if constexpr (std::is_same_v<Arg, const char*>)
    {
      (self->*set)(std::get<std::string>(value).c_str());
    }
    else
    {
      static_assert(std::is_same_v<Arg, const double*> || std::is_same_v<Arg, double*>,
        "unsupported setter argument");
      std::array<double, 3> v = std::get<std::array<double, 3>>(value);
      (self->*set)(v.data());
    }
  };
  this->Getter = [get](vtkObject* object) -> Value {
    C* self = static_cast<C*>(object);
    using Ret = std::decay_t<G>;
    if constexpr (std::is_same_v<Ret, bool>)
    {
      return (self->*get)();
    }
    else if constexpr (std::is_integral_v<Ret>)
    {
      return static_cast<long long>((self->*get)());
    }
    else if constexpr (std::is_floating_point_v<Ret>)
    {
      return static_cast<double>((self->*get)());
    }
    else if constexpr (std::is_same_v<Ret, const char*> || std::is_same_v<Ret, char*>)
    {
      const char* s = (self->*get)();
      return std::string(s ? s : "");
    }
    else
    {
      static_assert(std::is_same_v<Ret, double*> || std::is_same_v<Ret, const double*>,
        "unsupported getter result");
      const double* v = (self->*get)();
      return std::array<double, 3>{ v[0], v[1], v[2] };
    }
  };
  return *this;
}

#endif
// VTK-HeaderTest-Exclude: vtkPlumeParameterTable.h
