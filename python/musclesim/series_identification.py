"""Identification from measured series (to be written)."""
