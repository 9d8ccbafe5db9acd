from physc.cli import main

raise SystemExit(main())
