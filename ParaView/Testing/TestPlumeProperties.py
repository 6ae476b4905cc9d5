"""pvbatch: every property of the plugin's XML reaches the C++ object.

For each Plume representation (through ParaView's composite representation,
as a user sets it: rep.PlumeVolumeSampleDistance = ...), for the Gaussian
Splat filter and for the Smoke Solver source, for every property generated from the class's parameter table:
 1. after creation the C++ getter (read back through the property's
    information-only twin "<Name>Info") equals the XML default. ParaView
    pushes the XML defaults into the new object, so this checks the push and
    the read-back, not that the XML defaults are the class's (measured: with
    halved XML defaults it still passes). That is guaranteed elsewhere: the
    XML is generated from the table, and Plume.ParameterTables.MatchClasses
    checks each class (the splatter too) against its table;
 2. after setting a value different from the default (within the range,
    another enumeration entry, the other boolean, a new string), the C++
    getter returns exactly that value (fails when the XML's command does not
    reach the setter: checked by generating Modified as the reals' command).
Also checks that each representation exposes every property of its mapper
proxy (nothing of the table is missing from the panel).

The panel hides a property that applies only under some options of a
choice (the tables' OnlyWith, e.g. PlumeLinesScale only with
PlumeLinesScaleMode "fixed"), by visibility decorators in its hints as
ParaView's own XML does. Checked: every decorator names a property of the
proxy the panel shows (the representation, with its exposed names; the
filter) and values of that property's enumeration, and, deciding as
ParaView's GenericDecorator does (visible when the named property holds the
value; a composite "or" when any of its decorators is), that PlumeLinesScale,
PlumeLinesLatticeStride, PlumeLinesScreenSpacing, PlumeLinesStreamletSegments,
PlumeVolumeIsoValue and the splat's VectorArrayName show exactly under their
options, over every option of their choice. Broken once: without the
decorators (2026-11-28) PlumeLinesScale showed in "auto".
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plume_pvtest as T
from paraview import servermanager as sm
from paraview import simple

T.load_plugin()
failures = []


def fail(msg):
    print("FAIL:", msg)
    failures.append(msg)


def table_properties(proxy):
    """Names of the properties that have an information twin (the generated ones)."""
    names = []
    it = proxy.NewPropertyIterator()
    it.Begin()
    while not it.IsAtEnd():
        name = it.GetKey()
        if not name.endswith("Info") and proxy.GetProperty(name + "Info") is not None:
            names.append(name)
        it.Next()
    return names


def elements(prop):
    return [prop.GetElement(i) for i in range(prop.GetNumberOfElements())]


def same_numbers(got, want):
    """Equal to 1e-12 relative; NaN equals NaN (an "automatic" parameter's unset default)."""
    def close(a, b):
        if math.isnan(a) or math.isnan(b):
            return math.isnan(a) and math.isnan(b)
        return abs(a - b) <= 1e-12 * max(1.0, abs(b))
    return len(got) == len(want) and all(close(a, b) for a, b in zip(got, want))


def new_value(prop):
    """A valid value different from the property's default."""
    cls = prop.GetClassName()
    default = elements(prop)
    if cls == "vtkSMStringVectorProperty":
        return ["plume_test_array"]
    enum = prop.FindDomain("vtkSMEnumerationDomain")
    if enum is not None:
        for i in range(enum.GetNumberOfEntries()):
            if enum.GetEntryValue(i) != default[0]:
                return [enum.GetEntryValue(i)]
    if prop.FindDomain("vtkSMBooleanDomain") is not None:
        return [1 - default[0]]
    rng = prop.FindDomain("vtkSMIntRangeDomain") or prop.FindDomain("vtkSMDoubleRangeDomain")
    out = []
    for i, d in enumerate(default):
        if math.isnan(d):  # automatic (unset): any finite value sets it
            out.append(0.25 + 0.125 * i)
            continue
        lo = rng.GetMinimum(i) if rng is not None and rng.GetMinimumExists(i) else None
        hi = rng.GetMaximum(i) if rng is not None and rng.GetMaximumExists(i) else None
        if cls == "vtkSMIntVectorProperty":
            v = d + 1 if hi is None or d + 1 <= hi else d - 1
        else:
            step = 0.25 + 0.125 * i
            if hi is not None and d + step > hi:
                v = d - (d - lo) * 0.5 if lo is not None else d - step
            else:
                v = d + step
        out.append(v)
    return out


def check(label, proxy, setter):
    """proxy: the object's own proxy (its Info twins); setter(name, value) sets it as a user would."""
    names = table_properties(proxy)
    if not names:
        fail("%s: no generated properties" % label)
    proxy.UpdatePropertyInformation()
    for name in names:
        prop = proxy.GetProperty(name)
        info = proxy.GetProperty(name + "Info")
        default = elements(prop)
        got = elements(info)
        if prop.GetClassName() == "vtkSMStringVectorProperty":
            same = got == default
        else:
            same = same_numbers(got, default)
        if not same:
            fail("%s.%s: C++ default %s, XML default %s" % (label, name, got, default))
    changed = {}
    for name in names:
        value = new_value(proxy.GetProperty(name))
        setter(name, value)
        changed[name] = value
    proxy.UpdatePropertyInformation()
    for name, value in changed.items():
        got = elements(proxy.GetProperty(name + "Info"))
        if isinstance(value[0], str):
            same = got == value
        else:
            same = same_numbers(got, value)
        if not same:
            fail("%s.%s: set %s, C++ returns %s" % (label, name, value, got))
    print("%s: %d properties, defaults and set values reach the C++ object" % (label, len(names)))
    return names


src = T.carotid()
contour = simple.Contour(Input=src, ContourBy=["POINTS", "scalars"], Isosurfaces=[120.0])
v = T.view()
cases = [
    (src, "Plume Volume", "PlumeVolumeRepresentation", "PlumeVolume"),
    (contour, "Plume Smoke Sheet", "PlumeSheetRepresentation", "PlumeSheet"),
    (src, "Plume Velocity Lines", "PlumeVelocityLinesRepresentation", "PlumeLines"),
]
for source, text, subproxy, prefix in cases:
    rep = simple.Show(source, v)
    rep.Representation = text
    # The exposed properties are the mapper proxy's own objects: their parent
    # is the mapper's proxy (GetSubProxy is not public in Python).
    anchor = None
    it = rep.SMProxy.NewPropertyIterator()
    it.Begin()
    while not it.IsAtEnd():
        if it.GetKey().startswith(prefix) and it.GetProperty().GetParent() is not None:
            parent = it.GetProperty().GetParent()
            if parent.GetXMLGroup() == "plume_mappers":
                anchor = parent
                break
        it.Next()
    if anchor is None:
        fail("%s: no property of a plume_mappers proxy exposed with prefix %s" % (text, prefix))
        continue
    mapper = anchor

    def set_on_rep(name, value, rep=rep, prefix=prefix):
        exposed = prefix + name
        if rep.SMProxy.GetProperty(exposed) is None:
            fail("%s: %s not exposed on the representation" % (rep.Representation, exposed))
            return
        rep.SetPropertyWithName(exposed, value if len(value) > 1 else value[0])
        rep.UpdateVTKObjects()

    check(text, mapper, set_on_rep)
    simple.Render(v)
    simple.Hide(source, v)

splat = simple.PlumeGaussianSplat(Input=contour)


def set_on_filter(name, value):
    splat.SetPropertyWithName(name, value if len(value) > 1 else value[0])
    splat.UpdateVTKObjects()


check("Plume Gaussian Splat", splat.SMProxy, set_on_filter)

simple.SetActiveSource(None)  # simple would connect it to the solver's first input (Obstacles)
solver = simple.PlumeSmokeSolver()


def set_on_solver(name, value):
    solver.SetPropertyWithName(name, value if len(value) > 1 else value[0])
    solver.UpdateVTKObjects()


check("Plume Smoke Solver", solver.SMProxy, set_on_solver)


def decorators(proxy, name):
    """The visibility decorators of a property's hints: [(property named, [values])]."""
    hints = proxy.GetProperty(name).GetHints()
    out = []
    for i in range(hints.GetNumberOfNestedElements() if hints is not None else 0):
        e = hints.GetNestedElement(i)
        if e.GetName() != "PropertyWidgetDecorator":
            continue
        if e.GetAttribute("type") == "GenericDecorator" and e.GetAttribute("mode") == "visibility":
            out.append((e.GetAttribute("property"), [e.GetAttribute("value")]))
        elif e.GetAttribute("type") == "CompositeDecorator":
            expression = e.GetNestedElement(0)
            if expression.GetName() != "Expression" or expression.GetAttribute("type") != "or":
                fail("%s: a composite decorator that is not an 'or' expression" % name)
                continue
            parts = [expression.GetNestedElement(j) for j in range(expression.GetNumberOfNestedElements())]
            names = {p.GetAttribute("property") for p in parts}
            if len(names) != 1:
                fail("%s: an 'or' of decorators on several properties %s" % (name, names))
                continue
            out.append((names.pop(), [p.GetAttribute("value") for p in parts]))
    return out


def shown(proxy, name):
    """Whether the panel shows `name`, deciding as ParaView's decorators do."""
    return all(str(proxy.GetProperty(ctrl).GetElement(0)) in values for ctrl, values in decorators(proxy, name))


def check_decorators(label, proxy, prefix, expected):
    """Plume's properties (names starting with `prefix`; ParaView's own have
    decorators of other kinds); expected: {property: (choice property,
    options under which it shows)}."""
    it = proxy.NewPropertyIterator()
    it.Begin()
    count = 0
    while not it.IsAtEnd():
        if not it.GetKey().startswith(prefix):
            it.Next()
            continue
        for ctrl, values in decorators(proxy, it.GetKey()):
            count += 1
            prop = proxy.GetProperty(ctrl)
            enum = prop.FindDomain("vtkSMEnumerationDomain") if prop is not None else None
            entries = [str(enum.GetEntryValue(i)) for i in range(enum.GetNumberOfEntries())] if enum else []
            if not entries or any(value not in entries for value in values):
                fail("%s.%s: decorator on %s = %s, not a choice of the panel's proxy" % (label, it.GetKey(), ctrl, values))
        it.Next()
    for name, (ctrl, options) in expected.items():
        enum = proxy.GetProperty(ctrl).FindDomain("vtkSMEnumerationDomain")
        seen = []
        for i in range(enum.GetNumberOfEntries()):
            proxy.GetProperty(ctrl).SetElement(0, enum.GetEntryValue(i))
            seen.append((enum.GetEntryText(i), shown(proxy, name)))
            if shown(proxy, name) != (enum.GetEntryText(i) in options):
                fail("%s.%s: %s with %s %s" % (label, name, "shown" if shown(proxy, name) else "hidden", ctrl,
                                               enum.GetEntryText(i)))
        print("%s.%s shown with %s: %s" % (label, name, ctrl, ", ".join(t for t, on in seen if on)))
    print("%s: %d visibility decorators on Plume's properties, each on a choice of the panel's proxy" %
          (label, count))
    if count < len(expected):
        fail("%s: fewer decorators than properties expected to have one" % label)


rep = simple.Show(src, v)
rep.Representation = "Plume Velocity Lines"
check_decorators("Plume Velocity Lines", rep.SMProxy, "PlumeLines", {
    "PlumeLinesScale": ("PlumeLinesScaleMode", {"fixed"}),
    "PlumeLinesLatticeStride": ("PlumeLinesRootMode", {"lattice"}),
    "PlumeLinesScreenSpacing": ("PlumeLinesRootMode", {"screen"}),
    "PlumeLinesStreamletSegments": ("PlumeLinesIntegrator", {"rk2", "rk4"})})
rep.Representation = "Plume Volume"
check_decorators("Plume Volume", rep.SMProxy, "PlumeVolume", {"PlumeVolumeIsoValue": ("PlumeVolumeRenderMode", {"isosurface"})})
check_decorators("Plume Gaussian Splat", splat.SMProxy, "", {"VectorArrayName": ("Mode", {"velocity"})})
T.finish(not failures)
