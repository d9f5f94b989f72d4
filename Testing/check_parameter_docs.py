#!/usr/bin/env python3
# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""ctest ParameterDocs: ParaView's help for the filter and the parameter
reference say the same, from the same table.

ParaView's help is the generated proxy (build/generated/NarrowVolumeReconstruction.xml):
its Documentation elements are what the panel's ? button and the property
tooltips show. The reference is the page the site shows
(doc/reference/parameters.md, which doc/_ext/nvdocs.py fills with
cmake/generate-properties.py's markdown()). For the filter, the page must hold
the proxy's long help and documentation word for word; for every property of
the table, the tooltip and the page's text must both be the table's doc with
its {OtherProperty} names filled in, the tooltip with the panel's labels and
the page with the properties' names, naming the same properties in the same
places; likewise for the read-only values the panel shows (the table's
RESULTS). Visible properties with a picture in doc/images/parameters show it.

    check_parameter_docs.py build/generated/NarrowVolumeReconstruction.xml
"""
import importlib.util
import os
import re
import sys
import xml.etree.ElementTree as ElementTree

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(HERE)
IMAGES = os.path.join(SOURCE, "doc", "images", "parameters")


def load(name, path):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def filled_names(template, text):
    """The names a text puts into the template's {Name} places, or None when
    the text is not the template filled in."""
    parts = re.split(r"\{([A-Za-z]+)\}", template)
    pattern = "".join(re.escape(part) if i % 2 == 0 else "(.+?)" for i, part in enumerate(parts))
    match = re.fullmatch(pattern, text, re.S)
    return match.groups() if match else None


def main(xml_path):
    generator = load("nv_generate_properties", os.path.join(SOURCE, "cmake", "generate-properties.py"))
    table = generator.load_module("narrowvolume_properties", generator.TABLE)
    page = generator.markdown(table, images_dir=IMAGES, images_url="../images/parameters/")
    page_docs = generator.reference_docs(page)
    proxy = ElementTree.parse(xml_path).getroot().find(".//SourceProxy[@name='NarrowVolumeReconstruction']")
    failures = []

    help_element = proxy.find("Documentation")
    for what, text in (("long_help", help_element.get("long_help")), ("documentation", help_element.text)):
        if text not in page:
            failures.append("the filter's %s (the ? button) is not on the reference page: %r" % (what, text))

    checked = pictures = 0
    # The properties, and the read-only values the panel shows beside them.
    for prop in list(table.PROPERTIES) + list(table.RESULTS):
        element = proxy.find("*[@name='%s']" % prop.name)
        tooltip = element.find("Documentation").text if element is not None else None
        text = page_docs.get(prop.name)
        if tooltip is None or text is None:
            failures.append("%s: %s" % (prop.name, "no tooltip in the proxy" if tooltip is None else "not on the page"))
            continue
        labels = filled_names(prop.doc, tooltip)
        names = filled_names(prop.doc, text)
        if labels is None:
            failures.append("%s: the tooltip is not the table's text:\n  %s\n  %s" % (prop.name, tooltip, prop.doc))
        elif names is None:
            failures.append("%s: the reference is not the table's text:\n  %s\n  %s" % (prop.name, text, prop.doc))
        else:
            for label, name in zip(labels, names):
                name = name.strip("`")
                if name not in table.BY_NAME or table.BY_NAME[name].label != label:
                    failures.append("%s: the tooltip names %r where the reference names %r" % (prop.name, label, name))
        image = os.path.join(IMAGES, prop.name + ".png")
        if os.path.exists(image):
            pictures += 1
            if "(../images/parameters/%s.png)" % prop.name not in page:
                failures.append("%s: doc/images/parameters/%s.png is not shown" % (prop.name, prop.name))
        elif prop in table.PROPERTIES and not prop.advanced:
            print("note: %s is shown in the panel and has no picture yet (doc/images/parameters/%s.png)"
                  % (prop.name, prop.name))
        checked += 1

    for failure in failures:
        print("FAILED: " + failure)
    print("ParameterDocs: %d properties, the filter's help and %d pictures checked; %d failures"
          % (checked, pictures, len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
