"""Root in the child's own language: keyword tables, translation and labels in English, Dutch,
Spanish, French and German (docs/languages.md). How a message is worded in them is below the
forms, in :mod:`rootlang.wording`; the message texts' translations are in ``messages/`` here.

Loading any of it loads :mod:`~rootlang.locale.lines`, which hands the catalogue how code is
written in each language."""

from rootlang.locale import lines as lines
