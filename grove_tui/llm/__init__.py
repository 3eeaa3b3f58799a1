"""Local model handling: discovery, loading, grammar-constrained generation, embedded default."""
