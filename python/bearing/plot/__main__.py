"""python3 -m bearing.plot FOLDER [--out DIR] [--format png|svg|pdf]"""

import sys

from .cli import main

sys.exit(main())
