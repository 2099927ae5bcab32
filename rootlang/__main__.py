from rootlang.cli import main

raise SystemExit(main())
