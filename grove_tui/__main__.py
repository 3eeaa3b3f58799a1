from grove_tui.cli import main

main()
