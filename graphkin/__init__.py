"""graphkin."""
