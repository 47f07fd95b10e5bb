"""One module per source paper for scripts/reproduce-papers; context.py is what they share."""
