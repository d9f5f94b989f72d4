# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Two pieces of the site that come from the sources rather than from doc/:

- the parameter reference (reference/parameters.md): its text is replaced,
  as Sphinx reads it, by what cmake/generate-properties.py makes from the
  property table (Python/_properties.py), the table that also makes the
  ParaView proxy's help; the pictures are doc/images/parameters/<name>.png,
  shown where the file exists;
- the C++ class reference: the directive ``.. vtkheader:: PATH`` reads a VTK
  class header and writes its class comment and each public group of
  declarations (``///@{ ... ///@}`` with its doc comment) as directives of
  Sphinx's C++ domain. VTK's Set/Get macros become the methods they declare.
  No doxygen: the header's own comments, as written.
"""
import importlib.util
import os
import re

from docutils import nodes
from docutils.parsers.rst import Directive, directives
from docutils.statemachine import StringList

HERE = os.path.dirname(os.path.abspath(__file__))
DOC = os.path.dirname(HERE)
SOURCE = os.path.dirname(DOC)
PARAMETERS_PAGE = "reference/parameters"


def _load(name, path):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def parameter_reference():
    """The parameter reference's Markdown, as generate-properties.py makes it, with the pictures."""
    generator = _load("nv_generate_properties", os.path.join(SOURCE, "cmake", "generate-properties.py"))
    table = generator.load_module("narrowvolume_properties", generator.TABLE)
    return generator.markdown(table, images_dir=os.path.join(DOC, "images", "parameters"),
                              images_url="../images/parameters/")


def _source_read(app, docname, source):
    if docname == PARAMETERS_PAGE:
        source[0] = parameter_reference()
        app.env.note_dependency(os.path.join(SOURCE, "Python", "_properties.py"))


# --- The C++ header.

def _comment_text(block):
    """The text of a /** ... */ comment, without the stars."""
    lines = []
    for line in block.splitlines():
        line = line.strip()
        line = re.sub(r"^/\*\*\s?|\s?\*/$", "", line)
        line = re.sub(r"^\*\s?", "", line)
        lines.append(line)
    while lines and not lines[0]:
        lines.pop(0)
    while lines and not lines[-1]:
        lines.pop()
    return lines


def _escape(text):
    """Plain text for reStructuredText: the header writes |phi0|, x_2 and a*b as plain characters."""
    return re.sub(r"([\\`*|_])", r"\\\1", text)


def _signatures(declaration):
    """The C++ signatures a declaration makes (VTK macros expanded), and a note."""
    declaration = " ".join(declaration.split())
    macro = re.match(r"(vtk\w+Macro)\((.*)\);?$", declaration)
    if macro:
        kind, args = macro.group(1), [a.strip() for a in macro.group(2).split(",")]
        name = args[0]
        if kind == "vtkSetMacro":
            return ["void Set%s(%s value)" % (name, args[1])], None
        if kind == "vtkGetMacro":
            return ["%s Get%s()" % (args[1], name)], None
        if kind == "vtkBooleanMacro":
            return ["void %sOn()" % name, "void %sOff()" % name], None
        if kind == "vtkSetClampMacro":
            return (["void Set%s(%s value)" % (name, args[1]), "%s Get%sMinValue()" % (args[1], name),
                     "%s Get%sMaxValue()" % (args[1], name)],
                    "Set%s clamps to [%s, %s]." % (name, args[2], args[3]))
        if kind in ("vtkGetVector3Macro", "vtkGetVectorMacro"):
            size = args[2] if kind == "vtkGetVectorMacro" else "3"
            return ["%s* Get%s()" % (args[1], name), "void Get%s(%s data[%s])" % (name, args[1], size)], None
        if kind in ("vtkNarrowVolumeSettingMacro", "vtkNarrowVolumeSwitchMacro", "vtkNarrowVolumeClampMacro"):
            kind_type = "bool" if kind == "vtkNarrowVolumeSwitchMacro" else args[1]
            out = ["void Set%s(%s value)" % (name, kind_type), "%s Get%s()" % (kind_type, name)]
            if kind == "vtkNarrowVolumeSwitchMacro":
                return out + ["void %sOn()" % name, "void %sOff()" % name], None
            if kind == "vtkNarrowVolumeClampMacro":
                return (out + ["%s Get%sMinValue()" % (kind_type, name), "%s Get%sMaxValue()" % (kind_type, name)],
                        "Set%s clamps to [%s, %s]." % (name, args[2], args[3]))
            return out, None
        if kind == "vtkNarrowVolumeResultMacro":  # a row of NV_RESULTS (_results_declarations)
            result_type, name, size = {"Text": "const char*"}.get(args[0], args[0]), args[1], int(args[2])
            if size == 1:
                return ["%s Get%s()" % (result_type, name)], None
            return ["%s* Get%s()" % (result_type, name),
                    "void Get%s(%s data[%d])" % (name, result_type, size)], None
        if kind == "vtkGetObjectMacro":
            return ["%s* Get%s()" % (args[1], name)], None
        return [], None  # vtkTypeMacro and the like: no method of this class's own
    declaration = re.sub(r"\s*\{.*\}\s*$", "", declaration)  # an inline body
    declaration = declaration.rstrip(";").strip()
    declaration = re.sub(r"\s*VTK_SIZEHINT\([^)]*\)", "", declaration)  # VTK's wrapping hint, not C++
    return [declaration], None


def _results_declarations(macro):
    """NV_RESULTS(macro) as the header expands it: macro(Type, Name, Size);
    for each row of the property table's RESULTS (nvSettingsTable.h)."""
    generator = _load("nv_generate_properties", os.path.join(SOURCE, "cmake", "generate-properties.py"))
    table = generator.load_module("narrowvolume_properties", generator.TABLE)
    return ["%s(%s, %s, %d);" % (macro, generator.result_type(r), r.name, r.size) for r in table.RESULTS]


def _declarations(lines):
    """Whole declarations (joined over lines) from a list of code lines."""
    out, current = [], ""
    for line in lines:
        code = line.split("//")[0].strip()
        if not code:
            continue
        results = re.match(r"NV_RESULTS\((\w+)\)$", code)
        if results:
            out += _results_declarations(results.group(1))
            continue
        current = (current + " " + code).strip()
        if current.endswith(";") or current.endswith("}"):
            out.append(current)
            current = ""
    return out


def header_directives(path):
    """reStructuredText of the class in a VTK header: the class comment, its enums and public groups."""
    text = open(path, encoding="utf-8").read()
    class_comment = re.search(r"/\*\*\s*\n\s*\*\s*@class.*?\*/", text, re.S).group(0)
    declaration = re.search(r"class \w+ (\w+) : public (\w+)", text)
    class_name, base = declaration.group(1), declaration.group(2)
    public = text[text.index("public:", declaration.end()) + len("public:"):text.index("protected:")]

    rst = [".. cpp:class:: %s : public %s" % (class_name, base), ""]
    body, section = [], "text"
    see_also = []
    for line in _comment_text(class_comment):
        if line.startswith("@class"):
            continue
        if line.startswith("@brief"):
            body += ["**%s**" % _escape(line[len("@brief"):].strip()), ""]
        elif line.startswith("@warning"):
            section = "warning"
            body += [".. note::", ""]
        elif line.startswith("@sa"):
            section = "sa"
        elif section == "sa":
            see_also += line.split()
        elif section == "warning":
            body.append(("   " + _escape(line)) if line else "")
        else:
            body.append(_escape(line))
    if see_also:
        body += ["", "See also VTK's " + ", ".join("``%s``" % name for name in see_also) + "."]
    rst += ["   " + line if line else "" for line in body] + [""]

    # The public part: enums, and the groups between ///@{ and ///@}.
    position = 0
    pattern = re.compile(r"(///[^@<\n][^\n]*\n\s*)?enum (\w+)\s*\{(.*?)\};"
                         r"|///@\{\s*(/\*\*.*?\*/)?(.*?)///@\}"
                         r"|^\s*(static \w+\* New\(\);|void PrintSelf\([^)]*\) override;)", re.S | re.M)
    for match in pattern.finditer(public, position):
        if match.group(2):
            rst += ["   .. cpp:enum:: %s" % match.group(2), ""]
            if match.group(1):
                rst += ["      " + _escape(match.group(1).strip()[3:].strip()), ""]
            for entry in match.group(3).splitlines():
                value = entry.split("//")[0].strip().rstrip(",").strip()
                if not value:
                    continue
                note = re.search(r"///<\s*(.*)", entry)
                rst += ["      .. cpp:enumerator:: %s" % value, ""]
                if note:
                    rst += ["         " + _escape(note.group(1)), ""]
        elif match.group(5) is not None:
            doc = _comment_text(match.group(4)) if match.group(4) else []
            signatures, notes = [], []
            for declaration_text in _declarations(match.group(5).splitlines()):
                made, note = _signatures(declaration_text)
                signatures += made
                if note:
                    notes.append(note)
            if not signatures:
                continue
            rst.append("   .. cpp:function:: " + signatures[0])
            rst += ["                     " + s for s in signatures[1:]]
            rst.append("")
            rst += ["      " + _escape(line) if line else "" for line in doc]
            if notes:
                rst += ["", "      " + " ".join(_escape(n) for n in notes)]
            rst.append("")
        elif match.group(6):
            rst += ["   .. cpp:function:: " + match.group(6).rstrip(";"), ""]
    return rst


class VtkHeader(Directive):
    """.. vtkheader:: ../../Filters/vtkX.h (relative to the page)"""
    required_arguments = 1
    has_content = False

    def run(self):
        env = self.state.document.settings.env
        relative, path = env.relfn2path(self.arguments[0])
        env.note_dependency(path)
        lines = header_directives(path)
        container = nodes.container()
        self.state.nested_parse(StringList(lines, source=path), self.content_offset, container)
        return container.children


def setup(app):
    app.connect("source-read", _source_read)
    directives.register_directive("vtkheader", VtkHeader)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}
