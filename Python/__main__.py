# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""python -m narrowvolume (or pvpython -m narrowvolume): the command line."""
import sys

from ._cli import main

sys.exit(main())
