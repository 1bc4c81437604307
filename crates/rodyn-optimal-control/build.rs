//! Links the system's IPOPT (Debian: `coinor-libipopt-dev`), found through
//! pkg-config. `cargo xtask test` installs it when it runs as root.

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    // Only libipopt itself is linked (by the `#[link]` in `src/ipopt.rs`):
    // the shared library brings its own LAPACK, BLAS and MUMPS, whose `-l`
    // flags in ipopt.pc would need their -dev packages for nothing.
    match pkg_config::Config::new()
        .atleast_version("3.11")
        .cargo_metadata(false)
        .probe("ipopt")
    {
        Ok(library) => {
            for path in library.link_paths {
                println!("cargo:rustc-link-search=native={}", path.display());
            }
        }
        Err(error) => {
            // Stop here with the one command that fixes it rather than let the
            // linker fail later with a list of undefined symbols.
            panic!(
                "rodyn-optimal-control needs the IPOPT library and its pkg-config file ({error}).\n\
                 Install it with: apt-get install coinor-libipopt-dev pkg-config"
            );
        }
    }
}
