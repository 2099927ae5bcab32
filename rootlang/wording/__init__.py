"""How a message reaches a person, below everything that produces one: the typed values a
message holds (:mod:`~rootlang.wording.shown`: a phrase, a code, a value in a unit), which
languages are in force (:mod:`~rootlang.wording.language`) and the catalogue that words a
message in them (:mod:`~rootlang.wording.catalogue`). The program's own words in other
languages (the keyword tables, translating lines and programs) stand above the forms, in
:mod:`rootlang.locale`, and hand the catalogue how code is written in a language."""
