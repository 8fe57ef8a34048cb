"""Figures drawn by gnuplot (to be written)."""
