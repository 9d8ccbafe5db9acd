from physc.console import main

raise SystemExit(main())
