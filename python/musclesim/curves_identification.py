"""Identification from measured curves (to be written)."""
