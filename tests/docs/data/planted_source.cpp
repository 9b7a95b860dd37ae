// The self-test of tests/docs/check_docs.py reads this file's comments: every line marked planted must be reported,
// and no other. What exists: docs/guide/rolling.md "Conventions", docs/design.md, section 2, geometry/cone_line.hpp.
// A README section that never was: README "No such section". [planted]
// A page that never was: docs/guide/nothing.md. [planted]
// A design section that never was: docs/design.md section 42. [planted]
// A header that never was: wheelset_contact.hpp. [planted]
// A section of a page that never was: docs/guide/rolling.md "No such heading". [planted]
int planted = 0;
