"""physc: a compiler for physics tasks.

A `.phys` scenario (a causal sequence of physical interactions plus restrictions)
is compiled into a task whose intended solution realises that sequence.
"""

__version__ = "0.1.0"
