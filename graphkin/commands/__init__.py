"""Sub-commands of the ``graphkin`` CLI, one module each (``add_parser`` and ``run``)."""
