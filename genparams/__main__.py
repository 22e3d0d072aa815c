import sys

from genparams.cli import main

sys.exit(main())
