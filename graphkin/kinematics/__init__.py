"""The book's constructions built from construction steps, and the analytic oracle."""
