// This build's identity (written at build time by cmake/WrcBuildId.cmake). A study records build_id() among its
// identity lines and refuses to resume the parts of another build (docs/guide/studies.md), whose results may differ
// although wrc's version (WRC_VERSION) is the same.
#pragma once

namespace wrc {

// 12 hex digits: a hash of the sources this binary was built from (engine, Lua library, plugins, shipped profiles,
// CMake files) and of the compiler and its flags. The same for every binary of one build; another for any change.
const char* build_id();
// For people: "git <commit>" (the last commit that changed those sources), with ", modified" when the working tree
// changed them; "git commit unknown" outside a git checkout.
const char* build_origin();

}  // namespace wrc
