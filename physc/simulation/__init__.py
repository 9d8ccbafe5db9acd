"""Simulation results that every domain and backend shares: traces."""
