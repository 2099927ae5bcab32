"""Root in the child's own language: keyword tables, translation, messages and labels in
English, Dutch, Spanish, French and German (docs/languages.md)."""
