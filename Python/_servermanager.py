# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""The filter's ParaView proxy (server-manager XML), made from the property table.

One function serves both plugins: the compiled plugin's XML, which
cmake/generate-properties.py writes when CMake configures, and the Python
plugin's (NarrowVolumePythonPlugin.py), which names its Python class. The
proxy is the same: name, label, menu, documentation, the input, the two
named outputs, every property with its label, default, domain, panel
group, advanced flag and documentation, and beside some of them the value
the last run chose (read-only information properties).

Only the standard library, and the table passed in (the generator loads
Python/_properties.py by its path, the package imports it).
"""
from typing import Any, List, Optional
from xml.sax.saxutils import escape, quoteattr

PROXY_NAME = "NarrowVolumeReconstruction"
PROXY_LABEL = "Narrow Volume Reconstruction"
MENU = "Point Interpolation"

LONG_HELP = ("Reconstructs a narrow volume (a thick shell of half-thickness OffsetDistance) around a point cloud "
             "by the phase-field (Allen-Cahn) method of Li et al., Pattern Recognition 2015.")
SHORT_HELP = "Thick shell around a point cloud."
DOCUMENTATION = (
    "Builds a uniform grid around the input points, computes the truncated distance to the points near the "
    "offset distance l, and evolves a phase field phi (about +1 inside the shell, -1 outside) by the "
    "Allen-Cahn equation on the narrow band around the shell's boundary only. Output 0 (Volume) is phi on "
    "the grid; output 1 (Surface) is phi = 0: the two offset sheets at distance l on either side of the "
    "points, as a closed triangle mesh with normals, ready to save as STL. Only the input's points are used.")


def number(value: Any) -> str:
    """A number as C++, XML and Markdown all read it: 0 rather than 0.0, 1e-06 as is."""
    text = repr(value)
    return text[:-2] if text.endswith(".0") else text


def result_element(table: Any, result: Any, indent: str, label: Any) -> List[str]:
    """A value the last run chose, as a read-only (information-only)
    property that the panel shows and updates after each Apply (unless its
    panel is "hidden": see panel_hints()); label(name): another property's
    panel label."""
    element, helper = {float: ("DoubleVectorProperty", "SimpleDoubleInformationHelper"),
                       int: ("IntVectorProperty", "SimpleIntInformationHelper"),
                       str: ("StringVectorProperty", "SimpleStringInformationHelper")}[result.kind]
    default = "" if result.kind is str else " ".join(["0"] * result.size)
    attributes = ('name="%s" command="Get%s" label=%s information_only="1" number_of_elements="%d" '
                  'default_values=%s panel_visibility="%s"' % (
                      result.name, result.name, quoteattr(result.label), result.size, quoteattr(default),
                      "advanced" if result.panel == "advanced" else "default"))
    return ["%s<%s %s>" % (indent, element, attributes),
            "%s  <%s/>" % (indent, helper),
            "%s  <Documentation>%s</Documentation>" % (indent, escape(table.describe(result, label))),
            "%s</%s>" % (indent, element)]


def lists_after(table: Any, name: str) -> List[Any]:
    """The list properties the panel shows after property `name`."""
    return [listed for listed in table.LIST_PROPERTIES if listed.after == name]


def list_element(table: Any, listed: Any, indent: str, label: Any) -> List[str]:
    """A list of points (x y z), set point by point as vtkContourFilter's
    values are: SetNumberOf<Name>(n), then Set<Name less s>(i, x, y, z)."""
    attributes = ('name="%s" command="Set%s" label=%s number_of_elements="0" default_values="none" '
                  'repeat_command="1" number_of_elements_per_command="3" use_index="1" '
                  'set_number_command="SetNumberOf%s"' % (
                      listed.name, table.singular(listed.name), quoteattr(listed.label), listed.name))
    if listed.advanced:
        attributes += ' panel_visibility="advanced"'
    return ["%s<DoubleVectorProperty %s>" % (indent, attributes),
            "%s  <Documentation>%s</Documentation>" % (indent, escape(table.describe(listed, label))),
            "%s</DoubleVectorProperty>" % indent]


def property_elements(table: Any, indent: str = "      ") -> List[str]:
    """The proxy's properties and their panel groups, in the table's order."""
    out = []
    label = lambda name: table.NAMED[name].label  # noqa: E731
    for prop in table.PROPERTIES:
        element = "DoubleVectorProperty" if prop.kind is float else "IntVectorProperty"
        default = int(prop.default) if prop.kind is bool else number(prop.default)
        attributes = 'name="%s" command="Set%s" label=%s number_of_elements="1" default_values="%s"' % (
            prop.name, prop.name, quoteattr(prop.label), default)
        if prop.advanced:
            attributes += ' panel_visibility="advanced"'
        out.append("%s<%s %s>" % (indent, element, attributes))
        inner = indent + "  "
        if prop.kind is bool:
            out.append('%s<BooleanDomain name="bool"/>' % inner)
        if prop.choices:
            out.append('%s<EnumerationDomain name="enum">' % inner)
            for choice in prop.choices:
                out.append("%s  <Entry value=\"%d\" text=%s/>" % (inner, choice.value, quoteattr(choice.label)))
            out.append("%s</EnumerationDomain>" % inner)
        if prop.widget and prop.widget[0] == "bounds":
            out.append('%s<BoundsDomain name="bounds" mode="scaled_extent" scale_factor="%s" default_mode="min">'
                       % (inner, number(prop.widget[1])))
            out.append('%s  <RequiredProperties>' % inner)
            out.append('%s    <Property function="Input" name="Input"/>' % inner)
            out.append('%s  </RequiredProperties>' % inner)
            out.append('%s</BoundsDomain>' % inner)
        elif prop.widget and prop.widget[0] == "slider":
            kind = "DoubleRangeDomain" if prop.kind is float else "IntRangeDomain"
            out.append('%s<%s name="range" min="%s" max="%s"/>' % (inner, kind, number(prop.widget[1]),
                                                                     number(prop.widget[2])))
        out.append("%s<Documentation>%s</Documentation>" % (inner, escape(table.describe(prop, label))))
        out.append("%s</%s>" % (indent, element))
        for result in table.results_beside(prop.name):
            out += result_element(table, result, indent, label)
        for listed in lists_after(table, prop.name):
            out += list_element(table, listed, indent, label)
    groups = []
    for prop in table.PROPERTIES:
        if not groups or groups[-1][0] != prop.group:
            groups.append((prop.group, [], []))
        groups[-1][1].append(prop.name)
        groups[-1][1].extend(result.name for result in table.results_beside(prop.name))
        groups[-1][1].extend(listed.name for listed in lists_after(table, prop.name))
        groups[-1][2].append(prop.name)
    for group, names, settings in groups:
        if group in table.GROUP_TITLES:
            group = table.GROUP_TITLES[group]
        elif table.AUTOMATIC_WHEN_ZERO.intersection(settings):
            group += " (0 = automatic)"
        out.append("%s<PropertyGroup label=%s>" % (indent, quoteattr(group)))
        out += ['%s  <Property name="%s"/>' % (indent, name) for name in names]
        out.append("%s</PropertyGroup>" % indent)
    return out


def panel_hints(table: Any, indent: str = "        ") -> List[str]:
    """The proxy's hints that keep the "hidden" results off the panel. Not
    panel_visibility="never": pvpython gives an information property with
    that no attribute (shell.GridDimensionsUsed), and scripts use them."""
    return ['%s<Property name="%s" show="0"/>' % (indent, result.name)
            for result in table.RESULTS if result.panel == "hidden"]


def proxy_xml(table: Any, python_class: Optional[str] = None) -> str:
    """The whole ServerManagerConfiguration of the filter: for the compiled
    plugin's C++ class, or, given python_class ("module.Class"), for a
    Python algorithm (ParaView's vtkSIPythonSourceProxy makes it)."""
    if python_class:
        proxy = 'class=%s si_class="vtkSIPythonSourceProxy"' % quoteattr(python_class)
    else:
        proxy = 'class="vtkNarrowVolumeReconstruction"'
    lines = [
        "<ServerManagerConfiguration>",
        '  <ProxyGroup name="filters">',
        '    <SourceProxy name="%s" %s label=%s>' % (PROXY_NAME, proxy, quoteattr(PROXY_LABEL)),
        "      <Documentation long_help=%s short_help=%s>%s</Documentation>" % (
            quoteattr(LONG_HELP), quoteattr(SHORT_HELP), escape(DOCUMENTATION)),
        '      <InputProperty name="Input" command="SetInputConnection">',
        '        <ProxyGroupDomain name="groups">',
        '          <Group name="sources"/>',
        '          <Group name="filters"/>',
        "        </ProxyGroupDomain>",
        '        <DataTypeDomain name="input_type">',
        '          <DataType value="vtkPointSet"/>',
        "        </DataTypeDomain>",
        "        <Documentation>The point cloud: any dataset with points (polydata, unstructured grid, "
        "...).</Documentation>",
        "      </InputProperty>",
        '      <OutputPort name="Volume" index="0"/>',
        '      <OutputPort name="Surface" index="1"/>',
    ]
    lines += property_elements(table)
    lines += [
        '      <IntVectorProperty name="PanelLabelsInMessages" command="SetPanelLabelsInMessages" '
        'number_of_elements="1" default_values="1" panel_visibility="never">',
        '        <BooleanDomain name="bool"/>',
        "        <Documentation>The filter's messages name the properties by these labels.</Documentation>",
        "      </IntVectorProperty>",
    ]
    lines += [
        "      <Hints>",
    ] + panel_hints(table) + [
        '        <ShowInMenu category="%s"/>' % MENU,
        '        <Visibility replace_input="0"/>',
        "      </Hints>",
        "    </SourceProxy>",
        "  </ProxyGroup>",
        "</ServerManagerConfiguration>",
        "",
    ]
    return "\n".join(lines)
