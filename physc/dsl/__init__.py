"""The `.phys` front end: grammar, lexer, parser, syntax tree, static checks, formatter."""
