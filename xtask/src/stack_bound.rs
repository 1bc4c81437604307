//! Worst-case stack bounds of the firmware images, from a static call graph.
//!
//! The cost table's stack bytes are painted-stack measurements: the most a
//! call used over 100 random states, a lower bound on what it can use. This
//! module bounds it from above, on the very images that were measured (the
//! `thumbv7em-none-eabihf` release ELFs of `firmware/`, not a rebuild with
//! other flags, so the bound and the painted figure describe the same code):
//!
//! * **Frames.** Each function's instructions (`llvm-objdump -d`) are read in
//!   address order, adding the bytes every `push`/`vpush`/`sub sp` takes and
//!   removing what every unconditional `pop`/`vpop`/`add sp` gives back; the
//!   frame is the deepest point. A conditional `pop` or `add sp` (in an `IT`
//!   block) gives nothing back, and after a return or a tail call the
//!   code that follows is taken to run at the deepest point seen so far
//!   (it is another path through the body): both can only overestimate.
//!   A store or load with write-back through `sp` (`str r11, [sp, #-4]!`)
//!   is a push or pop of one register. Any other instruction that writes
//!   `sp` is reported and fails the check, since it would make the frame
//!   unknown (none is found in today's images). `cargo xtask stack
//!   --check-frames` compares every frame read this way with LLVM's own
//!   figure (`-Z emit-stack-sizes`, in a separate build): all agree today.
//! * **Calls.** `bl` to a function is a call from the full frame; a branch
//!   (`b`, `b.w`, `beq.w`, `cbz`, …) to another function is a tail call,
//!   from the depth at that point (zero after the epilogue); a call into
//!   the middle of a function fails the check like an unknown move of `sp`
//!   (none today). Indirect calls
//!   (`blx rN`, `bx rN`, `ldr pc`, `mov pc`) cannot be followed: they are
//!   listed per function, with the depth they are made at and the source
//!   function they were inlined from, never silently dropped. In rodyn they
//!   are the calls to a custom joint through `&dyn JointModel`, so the
//!   bounds hold for models of built-in joints; a custom joint adds its own
//!   worst case on top of the depth reported for those call sites.
//! * **Recursion.** A bound is the deepest *simple* path: a call back into
//!   a function already on the path is not followed. Recursion itself has
//!   no static bound, so cycles are found (strongly connected components)
//!   and reported with their functions. The only one in today's images is
//!   the panic handler's: a panic while defmt's logger is held (or in
//!   defmt's own bounds checks) enters the handler again, which logs
//!   through defmt again (issue 22 item 2 removes the panic paths). The
//!   bounds hold for executions that do not panic inside the panic
//!   handler; the check fails on any other cycle.
//! * **Entries.** The reset handler (which calls `main`) and every handler of
//!   the vector table. An exception stacks its frame on the same (main)
//!   stack: with the FPU's lazy context, 26 words and 4 bytes of alignment.
//!   The image's bound is the reset handler's plus the deepest handler's
//!   with that frame: one exception active at a time (the examples enable no
//!   interrupt; only a fault can enter a handler).
//!
//! Each row of the cost table is measured by one `call_opaque` instance
//! (`firmware/src/measure/`), which the debug information names by its
//! closure (`call_opaque<bool, &mut cost_probe::probe::{closure_env#0}<7, 7,
//! 7, …>>`); [`ROWS`] says which instance measures which row, and the row's
//! bound is that instance's. `cost_probe` runs the four algorithms of one
//! model through one closure (a `match` on the algorithm), so those four
//! rows share the bound of the deepest of them. The painted figure counts
//! the bytes used below the measuring code's stack pointer, which is where
//! `call_opaque`'s frame starts, so bound and measurement count the same
//! bytes and `cargo xtask test` fails when a measurement exceeds its bound.

use crate::firmware::{self, EXAMPLES};
use crate::setup;
use addr2line::gimli;
use anyhow::{bail, Context, Result};
use object::{Object, ObjectSection, ObjectSymbol};
use std::borrow::Cow;
use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::fmt::Write;
use std::path::Path;
use std::process::Command;

/// Bytes the core stacks on exception entry with an active FPU context
/// (lazy stacking reserves S0-S15 and FPSCR: 26 words), plus the word of
/// padding that keeps the stack 8-byte aligned.
pub const EXCEPTION_FRAME_BYTES: u64 = 26 * 4 + 4;

/// Which probe closure measures which cost-table row: (image, model,
/// algorithm, text of the `call_opaque` instance's debug name). The text
/// names the row's closures by their index in the probe function's source
/// (`{closure_env#1}` is the second closure written in it); a row that
/// matches no instance fails the check, so a reordered probe cannot pass
/// unnoticed with another row's bound.
pub const ROWS: &[(&str, &str, &str, &str)] = &[
    (
        "cost_probe",
        "pendulum",
        "*",
        "probe::{closure_env#0}<1, 1, 1, rodyn::spatial::Spatial>",
    ),
    (
        "cost_probe",
        "pendulum-planar",
        "*",
        "probe::{closure_env#0}<1, 1, 1, rodyn::planar::Planar>",
    ),
    (
        "cost_probe",
        "panda-7dof",
        "*",
        "probe::{closure_env#0}<7, 7, 7, rodyn::spatial::Spatial>",
    ),
    (
        "cost_probe",
        "quadruped-floating",
        "*",
        "probe::{closure_env#0}<13, 19, 18, rodyn::spatial::Spatial>",
    ),
    (
        "cost_probe",
        "muscle-robot",
        "FD+4-muscles",
        "probe_muscle_robot::{closure_env#1}>",
    ),
    (
        "cost_probe",
        "muscle-robot",
        "FD+dqdd/da",
        "probe_muscle_robot::{closure_env#2}>",
    ),
    (
        "cost_probe",
        "quadruped-contact",
        "step(SIE,ABA)",
        "probe_quadruped_step::{closure_env#1}>",
    ),
    (
        "control_cost_probe",
        "panda-7dof",
        "flange-Jacobian",
        "probe_flange::{closure_env#1}>",
    ),
    (
        "control_cost_probe",
        "panda-7dof",
        "flange-Jdot-v",
        "probe_flange::{closure_env#2}>",
    ),
    (
        "control_cost_probe",
        "panda-7dof",
        "IK-step",
        "probe_flange::{closure_env#4}>",
    ),
    (
        "control_cost_probe",
        "panda-7dof",
        "task-space-tick",
        "probe_task_space_tick::{closure_env#2}>",
    ),
    (
        "control_cost_probe",
        "panda-7dof",
        "RNEA-derivatives",
        "probe_derivatives::{closure_env#1}>",
    ),
    (
        "control_cost_probe",
        "panda-7dof",
        "ABA-derivatives",
        "probe_derivatives::{closure_env#2}>",
    ),
    (
        "control_cost_probe",
        "muscle-robot",
        "dqdd/d(q,v)",
        "probe_muscle_robot_derivatives::{closure_env#1}>",
    ),
    (
        "control_cost_probe",
        "pendulum",
        "MPC-tick(iLQR,25)",
        "probe_mpc_tick::{closure_env#1}>",
    ),
    (
        "contact_cost_probe",
        "quadruped-rigid",
        "constrained-FD(4-feet)",
        "probe_quadruped_contacts::{closure_env#2}>",
    ),
    (
        "contact_cost_probe",
        "quadruped-rigid",
        "constrained-FD-ABM(4-feet)",
        "probe_quadruped_contacts::{closure_env#3}>",
    ),
    (
        "contact_cost_probe",
        "quadruped-rigid",
        "impulse(4-feet)",
        "probe_quadruped_contacts::{closure_env#4}>",
    ),
    (
        "contact_cost_probe",
        "quadruped-rigid",
        "rigid-step(4-feet)",
        "probe_quadruped_contacts::{closure_env#5}>",
    ),
    (
        "contact_cost_probe",
        "quadruped-rigid",
        "rigid-step(feet-up)",
        "probe_quadruped_contacts::{closure_env#5}>",
    ),
    (
        "contact_cost_probe",
        "quadruped-rigid",
        "control-tick(2-feet)",
        "probe_quadruped_contacts::{closure_env#7}>",
    ),
    (
        "contact_cost_probe",
        "quadruped-rigid",
        "control-tick(4-feet)",
        "probe_quadruped_contacts::{closure_env#8}>",
    ),
    (
        "contact_cost_probe",
        "quadruped-floating",
        "joint-Jacobians",
        "probe_quadruped_kinematics::{closure_env#1}>",
    ),
    (
        "contact_cost_probe",
        "quadruped-floating",
        "CCRBA",
        "probe_quadruped_kinematics::{closure_env#2}>",
    ),
    (
        "contact_cost_probe",
        "quadruped-floating",
        "foot-Jacobian",
        "probe_quadruped_kinematics::{closure_env#3}>",
    ),
    (
        "contact_cost_probe",
        "quadruped-floating",
        "four-feet-Jacobians",
        "probe_quadruped_kinematics::{closure_env#4}>",
    ),
    (
        "update_cost_probe",
        "panda-7dof",
        "model-update(stage+publish)",
        "probe_update::{closure_env#1}>",
    ),
    (
        "update_cost_probe",
        "panda-7dof",
        "model-read(tick)",
        "probe_update::{closure_env#3}>",
    ),
];

/// A call from one function to another.
#[derive(Debug, Clone, Copy)]
struct Call {
    /// The callee (index into [`Graph::functions`]).
    target: usize,
    /// Stack bytes of the caller below its entry when the callee starts.
    depth: u64,
}

/// A call through a register: its target is not known statically.
#[derive(Debug, Clone, Copy)]
struct IndirectSite {
    address: u64,
    /// Stack bytes of the caller below its entry at the call.
    depth: u64,
}

/// One function of the image.
#[derive(Debug, Default)]
struct Function {
    /// Mangled symbol name.
    name: String,
    start: u64,
    /// Bytes of code (the symbol's size, else up to its last instruction).
    bytes: u64,
    /// Deepest point of its own frame (bytes).
    frame: u64,
    calls: Vec<Call>,
    indirect: Vec<IndirectSite>,
    /// Instructions that write `sp` in a way the frame reading does not know.
    unknown_sp: Vec<String>,
}

/// The call graph of one image.
pub struct Graph {
    functions: Vec<Function>,
    /// Entry points: (vector name, function).
    entries: Vec<(String, usize)>,
    /// Debug names of out-of-line functions, by start address.
    debug_names: BTreeMap<u64, String>,
    elf: std::path::PathBuf,
}

/// A worst-case stack bound from one function down.
#[derive(Debug, Clone, Default)]
pub struct Bound {
    /// Bytes over every direct call path.
    pub bytes: u64,
    /// The deepest path (function indices, caller first).
    path: Vec<usize>,
    /// The deepest indirect call site reached: stack bytes at that call
    /// (below the root's entry), and the path to the function making it.
    indirect: Option<(u64, Vec<usize>)>,
    /// Functions holding indirect calls reachable from here.
    indirect_in: BTreeSet<usize>,
    /// The functions of a call cycle (a strongly connected component)
    /// reached from here, if any.
    recursion: Option<Vec<usize>>,
}

/// Reads a register list `{r4, r5, lr}` or `{d8-d15}`: the registers in it
/// and whether it holds `pc`.
fn register_list(operands: &str) -> Option<(u64, bool)> {
    let inner = operands.split_once('{')?.1.split_once('}')?.0;
    let mut count = 0;
    let mut pc = false;
    for register in inner.split(',').map(str::trim) {
        if register == "pc" {
            pc = true;
        }
        count += match register.split_once('-') {
            Some((a, b)) => {
                let number = |r: &str| r[1..].parse::<u64>().ok();
                number(b)? - number(a)? + 1
            }
            None => 1,
        };
    }
    Some((count, pc))
}

/// Bytes per register of a register list (`d` registers are 8 bytes).
fn register_bytes(operands: &str) -> u64 {
    if operands.contains("{d") {
        8
    } else {
        4
    }
}

/// The immediate of `sub sp, #N` / `sub.w sp, sp, #N` / `subw sp, sp, #N`.
fn immediate(operands: &str) -> Option<u64> {
    let text = operands.rsplit_once('#')?.1.split_whitespace().next()?;
    match text.strip_prefix("0x") {
        Some(hex) => u64::from_str_radix(hex, 16).ok(),
        None => text.parse().ok(),
    }
}

/// The ARM condition codes, which suffix a mnemonic inside an `IT` block
/// (`al`, always, is no condition).
const CONDITIONS: [&str; 16] = [
    "eq", "ne", "cs", "hs", "cc", "lo", "mi", "pl", "vs", "vc", "hi", "ls", "ge", "lt", "gt", "le",
];

/// Splits a mnemonic into its base and whether it has a condition code
/// (`popne.w` → (`pop`, true)); `base` must be one of `bases`.
fn conditional<'a>(mnemonic: &str, bases: &[&'a str]) -> Option<(&'a str, bool)> {
    let plain = mnemonic
        .strip_suffix(".w")
        .or_else(|| mnemonic.strip_suffix(".n"))
        .unwrap_or(mnemonic);
    bases
        .iter()
        .find_map(|&base| match plain.strip_prefix(base)? {
            "" | "al" => Some((base, false)),
            rest if CONDITIONS.contains(&rest) => Some((base, true)),
            _ => None,
        })
}

/// The target address of a direct branch: `0x1234 <symbol+0x8>` (after
/// any register operand, as in `cbz r0, 0x1234 <…>`).
fn branch_target(operands: &str) -> Option<u64> {
    let hex = operands
        .split_whitespace()
        .find_map(|w| w.strip_prefix("0x"))?;
    u64::from_str_radix(hex, 16).ok()
}

/// One instruction of the disassembly.
struct Instruction<'a> {
    address: u64,
    mnemonic: &'a str,
    operands: &'a str,
}

/// A function's instructions as `llvm-objdump` printed them.
struct Listing<'a> {
    names: Vec<&'a str>,
    start: u64,
    instructions: Vec<Instruction<'a>>,
}

/// Splits `llvm-objdump -d --no-show-raw-insn` output into functions; a
/// symbol with no instructions of its own is an alias of the next.
fn listings(text: &str) -> Vec<Listing<'_>> {
    let mut listings: Vec<Listing> = Vec::new();
    let mut pending_names = Vec::new();
    for line in text.lines() {
        if let Some(header) = line.strip_suffix(">:") {
            let Some((address, name)) = header.split_once(" <") else {
                continue;
            };
            if name.starts_with('$') {
                continue; // a mapping symbol (`$t`, `$d`) inside a function
            }
            let Ok(start) = u64::from_str_radix(address, 16) else {
                continue;
            };
            pending_names.push(name);
            listings.push(Listing {
                names: Vec::new(),
                start,
                instructions: Vec::new(),
            });
            continue;
        }
        let Some((address, rest)) = line.trim_start().split_once(':') else {
            continue;
        };
        let Ok(address) = u64::from_str_radix(address, 16) else {
            continue;
        };
        // `<raw bytes or blanks>\t<mnemonic>\t<operands> @ <comment>`
        let rest = rest.split(" @ ").next().unwrap_or("");
        let mut fields = rest.split('\t').skip(1);
        let mnemonic = fields.next().unwrap_or("").trim();
        let operands = fields.next().unwrap_or("").trim();
        if mnemonic.is_empty() || mnemonic.starts_with('.') {
            continue; // data: `.word`, `.short`
        }
        let Some(listing) = listings.last_mut() else {
            continue;
        };
        if listing.instructions.is_empty() {
            listing.names.append(&mut pending_names);
        }
        listing.instructions.push(Instruction {
            address,
            mnemonic,
            operands,
        });
    }
    listings.retain(|l| !l.instructions.is_empty());
    listings
}

/// The functions of a disassembly, each ended at its symbol's size (when
/// `sizes` has one), with their frames, calls and indirect calls.
fn functions(text: &str, sizes: &HashMap<u64, u64>) -> Vec<Function> {
    let mut listings = listings(text);
    for listing in &mut listings {
        if let Some(size) = sizes.get(&listing.start) {
            let end = listing.start + size;
            listing.instructions.retain(|i| i.address < end);
        }
    }
    listings.retain(|l| !l.instructions.is_empty());
    let starts: Vec<u64> = listings.iter().map(|l| l.start).collect();
    let ends: Vec<u64> = listings
        .iter()
        .map(|l| l.instructions.last().map_or(l.start, |i| i.address))
        .collect();
    let containing = |address: u64| -> Option<usize> {
        let k = starts.partition_point(|&s| s <= address).checked_sub(1)?;
        (address <= ends[k]).then_some(k)
    };
    let mut functions = Vec::new();
    for (k, listing) in listings.iter().enumerate() {
        let mut reading = read_function(listing, |t| containing(t) == Some(k));
        let mut calls = Vec::new();
        for (address, target, depth) in reading.calls {
            match containing(target) {
                Some(callee) => {
                    if starts[callee] != target {
                        // Entered past its prologue: its frame from there
                        // is not what its entry's reading says.
                        reading.unknown_sp.push(format!(
                            "{address:#x}: a call into the middle of a function ({target:#x})"
                        ));
                    }
                    calls.push(Call {
                        target: callee,
                        depth,
                    });
                }
                // A branch to no function's code: as unknown as an
                // indirect call.
                None => reading.indirect.push(IndirectSite { address, depth }),
            }
        }
        functions.push(Function {
            name: listing.names.last().copied().unwrap_or("?").to_string(),
            start: listing.start,
            bytes: sizes
                .get(&listing.start)
                .copied()
                .unwrap_or(ends[k] + 2 - listing.start),
            frame: reading.frame,
            calls,
            indirect: reading.indirect,
            unknown_sp: reading.unknown_sp,
        });
    }
    functions
}

/// What a function's instructions do to the stack.
struct Reading {
    frame: u64,
    /// (address, target, depth) of each direct call or tail call.
    calls: Vec<(u64, u64, u64)>,
    indirect: Vec<IndirectSite>,
    unknown_sp: Vec<String>,
}

/// Reads one function's frame, calls and indirect calls (see the module
/// documentation for the rules).
fn read_function(listing: &Listing, contains: impl Fn(u64) -> bool) -> Reading {
    let mut depth: u64 = 0;
    let mut deepest: u64 = 0;
    let mut resume_at_deepest = false;
    let mut calls = Vec::new();
    let mut indirect = Vec::new();
    let mut unknown_sp = Vec::new();
    // Calls (not tail calls) are charged the whole frame: the callee may
    // run from any point of the body.
    let mut call_sites = Vec::new();
    for i in &listing.instructions {
        if resume_at_deepest {
            depth = deepest;
            resume_at_deepest = false;
        }
        let (m, ops) = (i.mnemonic, i.operands);
        if let Some((base, _)) = conditional(m, &["push", "vpush", "stmdb"]) {
            // A conditional push (on one path only) counts all the same.
            if base != "stmdb" || ops.starts_with("sp!") {
                if let Some((n, _)) = register_list(ops) {
                    depth += n * register_bytes(ops);
                }
            }
        } else if let Some((base, cond)) = conditional(m, &["pop", "vpop", "ldm", "ldmia"]) {
            if base.starts_with("ldm") && !ops.starts_with("sp!") {
                if ops.contains("pc") {
                    indirect.push(IndirectSite {
                        address: i.address,
                        depth,
                    });
                }
            } else if let Some((n, pc)) = register_list(ops) {
                if !cond {
                    depth = depth.saturating_sub(n * register_bytes(ops));
                    resume_at_deepest |= pc;
                }
            }
        } else if let Some((base, cond)) = conditional(m, &["sub", "subw", "add", "addw"]) {
            if ops.starts_with("sp,") {
                match immediate(ops) {
                    Some(n) if base.starts_with("sub") => depth += n,
                    Some(n) => {
                        if !cond {
                            depth = depth.saturating_sub(n);
                        }
                    }
                    None => unknown_sp.push(format!("{:#x}: {m} {ops}", i.address)),
                }
            }
        } else if conditional(m, &["bl"]).is_some() {
            if let Some(target) = branch_target(ops) {
                call_sites.push((i.address, target));
            }
        } else if conditional(m, &["blx"]).is_some() {
            // A register operand: an indirect call from the full frame.
            indirect.push(IndirectSite {
                address: i.address,
                depth: u64::MAX, // the frame, filled in below
            });
        } else if let Some((_, cond)) = conditional(m, &["bx"]) {
            if ops != "lr" {
                indirect.push(IndirectSite {
                    address: i.address,
                    depth,
                });
            }
            resume_at_deepest |= !cond;
        } else if let Some((base, cond)) = conditional(m, &["b", "cbz", "cbnz"]) {
            let target = branch_target(ops);
            if let Some(target) = target.filter(|&t| !contains(t)) {
                calls.push((i.address, target, depth));
                resume_at_deepest |= base == "b" && !cond;
            } else if base == "b" && !cond {
                // A jump within the function: the code after it is
                // reached from elsewhere, at an unknown depth.
                resume_at_deepest = true;
            }
        } else if let Some(n) = single_register_push(m, ops) {
            // `str r11, [sp, #-4]!`: a push of one register.
            depth += n;
        } else if let Some(n) = single_register_pop(m, ops) {
            // `ldr r11, [sp], #4`: a pop of one register.
            depth = depth.saturating_sub(n);
            if ops.starts_with("pc,") {
                resume_at_deepest = true;
            }
        } else if (m.starts_with("mov") || m.starts_with("ldr")) && ops.starts_with("pc,") {
            indirect.push(IndirectSite {
                address: i.address,
                depth,
            });
        } else if writes_sp(m, ops) {
            unknown_sp.push(format!("{:#x}: {m} {ops}", i.address));
        }
        deepest = deepest.max(depth);
    }
    for site in &mut indirect {
        if site.depth == u64::MAX {
            site.depth = deepest;
        }
    }
    calls.extend(
        call_sites
            .into_iter()
            .map(|(address, target)| (address, target, deepest)),
    );
    Reading {
        frame: deepest,
        calls,
        indirect,
        unknown_sp,
    }
}

/// Bytes pushed by a pre-indexed store with write-back through `sp`
/// (`str r11, [sp, #-4]!`, `strd r4, r5, [sp, #-8]!`), unconditional.
fn single_register_push(mnemonic: &str, operands: &str) -> Option<u64> {
    if !matches!(mnemonic, "str" | "str.w" | "strd" | "vstr") {
        return None;
    }
    let offset = operands.split_once("[sp, #-")?.1.strip_suffix("]!")?;
    immediate(&format!("#{offset}"))
}

/// Bytes popped by a post-indexed load with write-back through `sp`
/// (`ldr r11, [sp], #4`), unconditional.
fn single_register_pop(mnemonic: &str, operands: &str) -> Option<u64> {
    if !matches!(mnemonic, "ldr" | "ldr.w" | "ldrd" | "vldr") {
        return None;
    }
    let offset = operands.split_once("[sp], #")?.1;
    immediate(&format!("#{offset}"))
}

/// Whether an instruction not handled above writes `sp` (as its
/// destination, or a load or store's write-back), which would make the
/// frame unknown.
fn writes_sp(mnemonic: &str, operands: &str) -> bool {
    let write_back =
        operands.contains("[sp") && (operands.contains("]!") || operands.contains("], "));
    // `vldm` loads FPU registers only: through `sp` without write-back
    // (`vldmia sp, {d0, d1}`, in the Cortex-M7's f64 image) it reads.
    let reads_only = [
        "str", "vstr", "stm", "vstm", "vldm", "cmp", "cmn", "tst", "teq", "pld",
    ];
    if reads_only.iter().any(|s| mnemonic.starts_with(s)) {
        return write_back || operands.starts_with("sp!");
    }
    operands.starts_with("sp,") || operands.starts_with("sp!") || operands == "sp" || write_back
}

impl Graph {
    /// Disassembles and reads one firmware ELF.
    pub fn of_elf(elf: &Path) -> Result<Self> {
        let objdump = setup::llvm_tool("llvm-objdump")?;
        let output = Command::new(objdump)
            .args(["-d", "--no-show-raw-insn"])
            .arg(elf)
            .output()
            .context("running llvm-objdump")?;
        if !output.status.success() {
            bail!(
                "llvm-objdump failed on {}: {}",
                elf.display(),
                String::from_utf8_lossy(&output.stderr)
            );
        }
        let text = String::from_utf8_lossy(&output.stdout);
        let data = std::fs::read(elf).with_context(|| format!("reading {}", elf.display()))?;
        let file = object::File::parse(&*data)?;
        // The symbol table's sizes end each function: the alignment padding
        // after it disassembles as instructions that are never run.
        let sizes: HashMap<u64, u64> = file
            .symbols()
            .filter(|s| s.kind() == object::SymbolKind::Text && s.size() > 0)
            .map(|s| (s.address() & !1, s.size()))
            .collect();
        let functions = functions(&text, &sizes);
        let containing = |address: u64| functions.iter().position(|f| f.start == address);
        // A handler is the start of a function.
        let entries = vector_table(&file)?
            .into_iter()
            .filter_map(|(name, address)| Some((name, containing(address & !1)?)))
            .collect();
        let debug_names = debug_names(&file)?;
        Ok(Self {
            functions,
            entries,
            debug_names,
            elf: elf.to_path_buf(),
        })
    }

    /// Code bytes of the functions reachable from `roots` (each counted once).
    pub fn reachable_code_bytes(&self, roots: &[usize]) -> u64 {
        let mut seen = vec![false; self.functions.len()];
        let mut stack = roots.to_vec();
        let mut bytes = 0;
        while let Some(k) = stack.pop() {
            if std::mem::replace(&mut seen[k], true) {
                continue;
            }
            bytes += self.functions[k].bytes;
            stack.extend(self.functions[k].calls.iter().map(|c| c.target));
        }
        bytes
    }

    /// Worst-case bounds of every function, with cycles found.
    ///
    /// The bound of a function is its deepest *simple* call path: a call
    /// back into a function already on the path is not followed, and the
    /// cycle is reported instead (recursion has no static bound; the only
    /// cycle in today's images is the panic handler's re-entry). Such a
    /// bound does not depend on the path that led to the function, so it is
    /// computed once per function: strongly connected components in reverse
    /// topological order, and within a component with a cycle every simple
    /// path (the components are a handful of functions).
    pub fn bounds(&self) -> Vec<Bound> {
        self.bounds_without(&vec![false; self.functions.len()])
    }

    /// [`Self::bounds`] with the calls to the `skipped` functions left out:
    /// the bound of the paths that do not enter them.
    pub fn bounds_without(&self, skipped: &[bool]) -> Vec<Bound> {
        let n = self.functions.len();
        let components = self.components(skipped);
        let mut component_of = vec![usize::MAX; n];
        for (c, members) in components.iter().enumerate() {
            for &k in members {
                component_of[k] = c;
            }
        }
        let mut bounds: Vec<Option<Bound>> = vec![None; n];
        // Tarjan's algorithm emits a component after every component it
        // reaches: each callee outside the component is bounded already.
        for members in &components {
            let cyclic = members.len() > 1
                || self.functions[members[0]]
                    .calls
                    .iter()
                    .any(|c| c.target == members[0]);
            for &k in members {
                let mut on_path = vec![false; n];
                let mut bound = self.simple_paths(k, skipped, &component_of, &bounds, &mut on_path);
                if cyclic {
                    bound.recursion = Some(members.clone());
                }
                bounds[k] = Some(bound);
            }
        }
        bounds.into_iter().map(Option::unwrap_or_default).collect()
    }

    /// The deepest simple path from `k`, exploring the calls within `k`'s
    /// component and taking the bounds of the components below as known.
    fn simple_paths(
        &self,
        k: usize,
        skipped: &[bool],
        component_of: &[usize],
        known: &[Option<Bound>],
        on_path: &mut Vec<bool>,
    ) -> Bound {
        let f = &self.functions[k];
        let mut bound = Bound {
            bytes: f.frame,
            path: vec![k],
            ..Bound::default()
        };
        for site in &f.indirect {
            bound.indirect_in.insert(k);
            if bound.indirect.as_ref().is_none_or(|(d, _)| site.depth > *d) {
                bound.indirect = Some((site.depth, vec![k]));
            }
        }
        on_path[k] = true;
        for call in &f.calls {
            if skipped[call.target] || on_path[call.target] {
                continue;
            }
            let callee = if component_of[call.target] == component_of[k] {
                self.simple_paths(call.target, skipped, component_of, known, on_path)
            } else {
                known[call.target].clone().unwrap_or_default()
            };
            if call.depth + callee.bytes > bound.bytes {
                bound.bytes = call.depth + callee.bytes;
                bound.path = std::iter::once(k)
                    .chain(callee.path.iter().copied())
                    .collect();
            }
            if let Some((d, p)) = &callee.indirect {
                if bound
                    .indirect
                    .as_ref()
                    .is_none_or(|(best, _)| call.depth + d > *best)
                {
                    bound.indirect = Some((
                        call.depth + d,
                        std::iter::once(k).chain(p.iter().copied()).collect(),
                    ));
                }
            }
            bound.indirect_in.extend(&callee.indirect_in);
            if bound.recursion.is_none() {
                bound.recursion.clone_from(&callee.recursion);
            }
        }
        on_path[k] = false;
        bound
    }

    /// The strongly connected components of the call graph without the
    /// `skipped` functions (Tarjan's algorithm, iterative), callees' first.
    fn components(&self, skipped: &[bool]) -> Vec<Vec<usize>> {
        let n = self.functions.len();
        let mut index = vec![usize::MAX; n];
        let mut low = vec![0; n];
        let mut on_stack = vec![false; n];
        let mut stack = Vec::new();
        let mut components = Vec::new();
        let mut next = 0;
        for root in 0..n {
            if index[root] != usize::MAX || skipped[root] {
                continue;
            }
            // (function, next call to look at)
            let mut work = vec![(root, 0)];
            index[root] = next;
            low[root] = next;
            next += 1;
            stack.push(root);
            on_stack[root] = true;
            while let Some(&mut (v, ref mut i)) = work.last_mut() {
                let calls = &self.functions[v].calls;
                if *i < calls.len() {
                    let w = calls[*i].target;
                    *i += 1;
                    if skipped[w] {
                        continue;
                    }
                    if index[w] == usize::MAX {
                        index[w] = next;
                        low[w] = next;
                        next += 1;
                        stack.push(w);
                        on_stack[w] = true;
                        work.push((w, 0));
                    } else if on_stack[w] {
                        low[v] = low[v].min(index[w]);
                    }
                    continue;
                }
                work.pop();
                if let Some(&(parent, _)) = work.last() {
                    low[parent] = low[parent].min(low[v]);
                }
                if low[v] == index[v] {
                    let mut members = Vec::new();
                    while let Some(w) = stack.pop() {
                        on_stack[w] = false;
                        members.push(w);
                        if w == v {
                            break;
                        }
                    }
                    components.push(members);
                }
            }
        }
        components
    }

    /// The core panic entry points (`core::panicking::*`, failed slice
    /// indexing, `unwrap` failures), as [`crate::panic_sites`] counts them.
    pub fn panic_entries(&self) -> Vec<bool> {
        (0..self.functions.len())
            .map(|k| {
                let name = self.name(k);
                crate::panic_sites::PANIC_ENTRIES
                    .iter()
                    .any(|entry| name.starts_with(entry.trim_start_matches('<')))
            })
            .collect()
    }

    /// A function's readable name: demangled, without its hash.
    pub fn name(&self, k: usize) -> String {
        short_name(&self.functions[k].name)
    }

    /// The functions whose debug name (with generic arguments) contains
    /// `text`.
    pub fn by_debug_name(&self, text: &str) -> Vec<usize> {
        self.debug_names
            .iter()
            .filter(|(_, name)| name.contains(text))
            .filter_map(|(&address, _)| self.functions.iter().position(|f| f.start == address))
            .collect()
    }

    /// `a → b → c` for a path.
    pub fn path_text(&self, path: &[usize]) -> String {
        path.iter()
            .map(|&k| format!("{} ({})", self.name(k), self.functions[k].frame))
            .collect::<Vec<_>>()
            .join(" → ")
    }

    /// `main (11736) → aba (384) → …`: the last segment of each name,
    /// without generic arguments, with its frame; from the first panic
    /// entry point on, one step with the panic path's bound.
    pub fn short_path(&self, path: &[usize], bounds: &[Bound]) -> String {
        let panics = self.panic_entries();
        let mut steps = Vec::new();
        for &k in path {
            let name = last_segment(&self.name(k));
            if panics[k] {
                steps.push(format!("{name} … (panic path {})", bounds[k].bytes));
                break;
            }
            steps.push(format!("{name} ({})", self.functions[k].frame));
        }
        steps.join(" → ")
    }

    /// The source functions (innermost inlined frame) of the indirect calls
    /// made in the given functions, e.g. `Joint::motion`.
    pub fn indirect_sources(&self, functions: &BTreeSet<usize>) -> Result<BTreeSet<String>> {
        let loader = addr2line::Loader::new(&self.elf)
            .map_err(|e| anyhow::anyhow!("cannot read the debug information: {e}"))?;
        let mut sources = BTreeSet::new();
        for &k in functions {
            for site in &self.functions[k].indirect {
                let mut frames = loader
                    .find_frames(site.address)
                    .map_err(|e| anyhow::anyhow!("address {:#x}: {e}", site.address))?;
                let name = match frames.next()? {
                    Some(frame) => frame
                        .function
                        .as_ref()
                        .and_then(|f| f.demangle().ok())
                        .map_or_else(|| format!("{:#x}", site.address), |n| short_name(&n)),
                    None => format!("{:#x}", site.address),
                };
                sources.insert(name);
            }
        }
        Ok(sources)
    }

    /// Instructions that move `sp` in a way the frame reading does not
    /// know, with their functions.
    pub fn unknown_sp(&self) -> Vec<String> {
        self.functions
            .iter()
            .flat_map(|f| {
                f.unknown_sp
                    .iter()
                    .map(|u| format!("{}: {u}", short_name(&f.name)))
            })
            .collect()
    }
}

/// The vector table's handlers: (name, address with the Thumb bit).
fn vector_table(file: &object::File) -> Result<Vec<(String, u64)>> {
    const NAMES: [&str; 16] = [
        "initial SP",
        "Reset",
        "NMI",
        "HardFault",
        "MemManage",
        "BusFault",
        "UsageFault",
        "reserved",
        "reserved",
        "reserved",
        "reserved",
        "SVCall",
        "DebugMonitor",
        "reserved",
        "PendSV",
        "SysTick",
    ];
    let section = file
        .section_by_name(".vector_table")
        .context("no .vector_table section")?;
    let data = section.data()?;
    let mut handlers = Vec::new();
    for (n, word) in data.chunks_exact(4).enumerate().skip(1) {
        let address = u64::from(u32::from_le_bytes(word.try_into()?));
        if address == 0 {
            continue;
        }
        let name = NAMES
            .get(n)
            .map_or_else(|| format!("IRQ{}", n - 16), |s| (*s).to_string());
        handlers.push((name, address));
    }
    Ok(handlers)
}

/// Debug names (with generic arguments) of the out-of-line `call_opaque`
/// instances, by start address: the symbol names only carry a hash.
fn debug_names(file: &object::File) -> Result<BTreeMap<u64, String>> {
    let load = |id: gimli::SectionId| -> Result<Cow<[u8]>> {
        Ok(file
            .section_by_name(id.name())
            .map(|s| s.uncompressed_data())
            .transpose()?
            .unwrap_or(Cow::Borrowed(&[])))
    };
    let sections = gimli::DwarfSections::load(load)?;
    let dwarf = sections.borrow(|s| gimli::EndianSlice::new(s, gimli::LittleEndian));
    let mut names = BTreeMap::new();
    let mut units = dwarf.units();
    while let Some(header) = units.next()? {
        let unit = dwarf.unit(header)?;
        let mut entries = unit.entries();
        while let Some((_, entry)) = entries.next_dfs()? {
            if entry.tag() != gimli::DW_TAG_subprogram {
                continue;
            }
            let Some(gimli::AttributeValue::Addr(low_pc)) =
                entry.attr_value(gimli::DW_AT_low_pc)?
            else {
                continue;
            };
            let Some(name) = entry.attr_value(gimli::DW_AT_name)? else {
                continue;
            };
            let name = dwarf
                .attr_string(&unit, name)?
                .to_string_lossy()
                .into_owned();
            if name.starts_with("call_opaque<") {
                names.insert(low_pc & !1, name);
            }
        }
    }
    Ok(names)
}

/// Demangled, without the hash, generic arguments kept.
fn short_name(name: &str) -> String {
    addr2line::demangle_auto(Cow::Borrowed(name), None).into_owned()
}

/// The worst case of one image: its entry points and their sum.
pub struct ImageBound {
    /// Image name.
    pub name: &'static str,
    /// The reset handler's bound (everything `main` does).
    pub thread: Bound,
    /// The deepest exception handler (name, bound), without its frame.
    pub handler: Option<(String, Bound)>,
    /// Reset + deepest handler + exception frame.
    pub total: u64,
    /// The deepest path from reset, with full names.
    pub thread_path: String,
    /// Sources of the indirect calls reachable from any entry.
    pub indirect_sources: BTreeSet<String>,
    /// The deepest indirect call site from reset: bytes at the call.
    pub indirect_depth: Option<u64>,
    /// The functions of a call cycle reachable from an entry, as text.
    pub recursion: Option<String>,
    /// [`Self::total`] over the paths that enter no panic entry point.
    pub total_without_panics: u64,
}

/// Bounds one image from its vector table.
pub fn image_bound(analysed: &Analysed, name: &'static str) -> Result<ImageBound> {
    let (graph, bounds) = (&analysed.graph, &analysed.bounds);
    let reset = graph
        .entries
        .iter()
        .find(|(n, _)| n == "Reset")
        .map(|&(_, k)| k)
        .context("no reset handler in the vector table")?;
    let thread = bounds[reset].clone();
    let mut handler: Option<(String, Bound)> = None;
    let mut indirect_in = thread.indirect_in.clone();
    let mut recursion = thread.recursion.clone();
    let mut seen = BTreeSet::new();
    for (vector, k) in &graph.entries {
        if vector == "Reset" || !seen.insert(*k) {
            continue;
        }
        let b = &bounds[*k];
        indirect_in.extend(&b.indirect_in);
        if recursion.is_none() {
            recursion.clone_from(&b.recursion);
        }
        if handler.as_ref().is_none_or(|(_, h)| b.bytes > h.bytes) {
            handler = Some((format!("{vector} ({})", graph.name(*k)), b.clone()));
        }
    }
    let total = thread.bytes
        + handler
            .as_ref()
            .map_or(0, |(_, h)| h.bytes + EXCEPTION_FRAME_BYTES);
    let without = &analysed.without_panics;
    let total_without_panics = without[reset].bytes
        + graph
            .entries
            .iter()
            .filter(|(vector, _)| vector != "Reset")
            .map(|&(_, k)| without[k].bytes + EXCEPTION_FRAME_BYTES)
            .max()
            .unwrap_or(0);
    Ok(ImageBound {
        name,
        thread_path: graph.path_text(&thread.path),
        indirect_depth: thread.indirect.as_ref().map(|(d, _)| *d),
        thread,
        handler,
        total,
        total_without_panics,
        indirect_sources: graph.indirect_sources(&indirect_in)?,
        recursion: recursion.map(|c| {
            c.iter()
                .map(|&k| graph.name(k))
                .collect::<Vec<_>>()
                .join(", ")
        }),
    })
}

/// `cargo xtask stack [image] [words…]`: builds the firmware, prints each
/// image's bound, runs the two cost probes and checks every row's painted
/// figure against its bound; with an image and words, also the bound of
/// every function of that image whose name contains them all.
/// `--frames <image>` lists each function's frame, `--check-frames`
/// compares the frames with LLVM's (see [`check_frames`]).
pub fn run(args: &[String]) -> Result<()> {
    setup::ensure_target()?;
    if args.first().is_some_and(|a| a == "--check-frames") {
        return check_frames();
    }
    setup::ensure_qemu()?;
    firmware::build()?;
    let images = analyse()?;
    if let [flag, image] = args {
        if flag == "--frames" {
            let Analysed { graph, .. } = &images[firmware::example(image)?.name];
            for f in &graph.functions {
                println!("{:#x} {} {}", f.start, f.frame, short_name(&f.name));
            }
            return Ok(());
        }
    }
    let selected: Vec<_> = match args.first() {
        Some(name) => vec![firmware::example(name)?.name],
        None => EXAMPLES.iter().map(|e| e.name).collect(),
    };
    for name in selected {
        let Analysed { graph, bounds, .. } = &images[name];
        let image = image_bound(&images[name], name)?;
        println!(
            "{}: {} bytes (reset {} + handler {} + exception frame {})",
            image.name,
            image.total,
            image.thread.bytes,
            image.handler.as_ref().map_or(0, |(_, h)| h.bytes),
            EXCEPTION_FRAME_BYTES
        );
        println!("  deepest path: {}", image.thread_path);
        if let Some((vector, h)) = &image.handler {
            println!("  deepest handler: {vector}: {}", graph.path_text(&h.path));
        }
        // Every entry, the vectors that share a handler together.
        let mut handlers: BTreeMap<usize, Vec<&str>> = BTreeMap::new();
        for (vector, k) in &graph.entries {
            handlers.entry(*k).or_default().push(vector);
        }
        for (k, vectors) in handlers {
            let listed = match vectors.len() {
                n if n > 6 => format!("{} and {} more vectors", vectors[..4].join(", "), n - 4),
                _ => vectors.join(", "),
            };
            println!(
                "  entry {listed} ({}): {} bytes",
                graph.name(k),
                bounds[k].bytes
            );
        }
        if !image.indirect_sources.is_empty() {
            println!(
                "  indirect calls (not followed), the deepest at {} bytes, from: {}",
                image.indirect_depth.unwrap_or(0),
                image
                    .indirect_sources
                    .iter()
                    .map(|s| last_segment(s))
                    .collect::<BTreeSet<_>>()
                    .into_iter()
                    .collect::<Vec<_>>()
                    .join(", ")
            );
        }
        if let Some(cycle) = &image.recursion {
            println!("  functions in a call cycle (each counted once per path): {cycle}");
        }
        for unknown in graph.unknown_sp() {
            println!("  unknown stack adjustment: {unknown}");
        }
        let words = &args[1.min(args.len())..];
        if !words.is_empty() {
            for (k, b) in bounds.iter().enumerate() {
                let function = graph.name(k);
                if words.iter().all(|w| function.contains(w.as_str())) {
                    println!("  {} bytes: {}", b.bytes, graph.path_text(&b.path));
                }
            }
        }
    }
    if args.is_empty() {
        let mut rows = Vec::new();
        for probe in crate::costs::PROBES {
            let outcome = firmware::run(firmware::example(probe)?, |_| {})?;
            if outcome.exit_code != 0 {
                bail!("{probe} exited with code {}", outcome.exit_code);
            }
            rows.extend(crate::costs::stack_rows(&crate::costs::parse_costs(
                &outcome.lines,
            )?));
        }
        check_rows(&images, &rows)?;
        check_images(&images)?;
    }
    Ok(())
}

/// One image's call graph and the bound of each of its functions.
pub struct Analysed {
    /// The call graph.
    pub graph: Graph,
    /// Bounds, by function.
    pub bounds: Vec<Bound>,
    /// Bounds of the paths that enter no panic entry point: what the
    /// images will need once issue 22 item 2 has removed the panic paths.
    pub without_panics: Vec<Bound>,
}

/// Reads every firmware image (after [`firmware::build`]).
pub fn analyse() -> Result<BTreeMap<&'static str, Analysed>> {
    EXAMPLES
        .iter()
        .map(|example| {
            let graph = Graph::of_elf(&firmware::elf(example))?;
            let bounds = graph.bounds();
            let without_panics = graph.bounds_without(&graph.panic_entries());
            Ok((
                example.name,
                Analysed {
                    graph,
                    bounds,
                    without_panics,
                },
            ))
        })
        .collect()
}

/// The bound of one cost-table row.
pub struct RowBound {
    /// Worst-case bytes below the measuring code's stack pointer.
    pub bytes: u64,
    /// The deepest path, short names with frames.
    pub path: String,
    /// Stack bytes at the deepest indirect (custom joint) call reached.
    pub indirect_depth: Option<u64>,
    /// The bound over the paths that enter no panic entry point.
    pub without_panics: u64,
}

/// The image and the `call_opaque` instances that measure the cost-table
/// row (`model`, `algorithm`), as [`ROWS`] names them.
fn row_roots<'a>(
    images: &'a BTreeMap<&'static str, Analysed>,
    model: &str,
    algorithm: &str,
) -> Result<(&'static str, &'static str, &'a Analysed, Vec<usize>)> {
    let (image, _, _, text) = ROWS
        .iter()
        .find(|(_, m, a, _)| *m == model && *a == algorithm)
        .or_else(|| ROWS.iter().find(|(_, m, a, _)| *m == model && *a == "*"))
        .with_context(|| {
            format!("stack_bound::ROWS names no probe closure for {model} {algorithm}")
        })?;
    let analysed = images
        .get(image)
        .with_context(|| format!("no image {image}"))?;
    let roots = analysed.graph.by_debug_name(text);
    Ok((image, text, analysed, roots))
}

/// The code bytes (flash) of every function the call of the cost-table row
/// (`model`, `algorithm`) can reach through direct calls and tail calls,
/// the measuring `call_opaque` instance included; rows measured through
/// one closure share the figure. Read-only data (the model's constants,
/// tables) is not counted.
pub fn row_code_bytes(
    images: &BTreeMap<&'static str, Analysed>,
    model: &str,
    algorithm: &str,
) -> Result<u64> {
    let (image, text, analysed, roots) = row_roots(images, model, algorithm)?;
    if roots.is_empty() {
        bail!("no call_opaque instance in {image} names `{text}` ({model} {algorithm})");
    }
    Ok(analysed.graph.reachable_code_bytes(&roots))
}

/// The bound of the cost-table row (`model`, `algorithm`): the deepest of
/// the `call_opaque` instances that [`ROWS`] names for it.
pub fn row_bound(
    images: &BTreeMap<&'static str, Analysed>,
    model: &str,
    algorithm: &str,
) -> Result<RowBound> {
    let (image, text, analysed, roots) = row_roots(images, model, algorithm)?;
    let deepest = roots
        .iter()
        .max_by_key(|&&k| analysed.bounds[k].bytes)
        .with_context(|| {
            format!(
                "no call_opaque instance in {image} names `{text}` ({model} {algorithm}): \
                 was the probe reordered? (update stack_bound::ROWS)"
            )
        })?;
    let bound = &analysed.bounds[*deepest];
    Ok(RowBound {
        bytes: bound.bytes,
        path: analysed.graph.short_path(&bound.path, &analysed.bounds),
        indirect_depth: roots
            .iter()
            .filter_map(|&k| analysed.bounds[k].indirect.as_ref().map(|(d, _)| *d))
            .max(),
        without_panics: roots
            .iter()
            .map(|&k| analysed.without_panics[k].bytes)
            .max()
            .unwrap_or(0),
    })
}

/// Checks each measured row against its bound: a painted figure above the
/// static bound means the analysis missed a frame or a call, so it fails.
/// `rows` are (model, algorithm, painted stack field of the `cost` line).
pub fn check_rows(
    images: &BTreeMap<&'static str, Analysed>,
    rows: &[(String, String, String)],
) -> Result<()> {
    let mut failures = Vec::new();
    for (model, algorithm, painted) in rows {
        if painted == "-" {
            continue; // not measured (a scalar function)
        }
        let bound = row_bound(images, model, algorithm)?;
        // `>16384`: the call overflowed the painted window.
        let painted_bytes: u64 = painted
            .trim_start_matches('>')
            .parse()
            .with_context(|| format!("stack figure `{painted}` of {model} {algorithm}"))?;
        let holds = if painted.starts_with('>') {
            bound.bytes > painted_bytes
        } else {
            bound.bytes >= painted_bytes
        };
        println!(
            "stack {model} {algorithm}: painted {painted}, static bound {}{}",
            bound.bytes,
            if holds {
                ""
            } else {
                "  <-- BELOW THE MEASUREMENT"
            }
        );
        if !holds {
            failures.push(format!("{model} {algorithm} ({painted} > {})", bound.bytes));
        }
    }
    if !failures.is_empty() {
        bail!(
            "the static stack bound is below the painted measurement for {}: \
             the analysis (xtask/src/stack_bound.rs) misses a frame or a call",
            failures.join(", ")
        );
    }
    Ok(())
}

/// Fails on a call cycle outside the panic handler's re-entry (which
/// issue 22 item 2 removes with the panic paths), and on any instruction
/// that moves `sp` in a way the frame reading does not know.
pub fn check_images(images: &BTreeMap<&'static str, Analysed>) -> Result<()> {
    for (name, analysed) in images {
        let image = image_bound(analysed, name)?;
        println!(
            "stack {name}: worst case {} bytes (main {}, handler and exception frame {})",
            image.total,
            image.thread.bytes,
            image.total - image.thread.bytes
        );
        if let Some(cycle) = &image.recursion {
            if !cycle.contains(PANIC_HANDLER) {
                bail!(
                    "{name}: a call cycle outside the panic handler makes the stack unbounded: {cycle}"
                );
            }
        }
        let unknown = analysed.graph.unknown_sp();
        if !unknown.is_empty() {
            bail!(
                "{name}: instructions move sp in a way xtask/src/stack_bound.rs does not read: {}",
                unknown.join("; ")
            );
        }
    }
    Ok(())
}

/// The panic handler's symbol: the only function a known cycle may pass
/// through (a panic while defmt's logger is held panics again).
const PANIC_HANDLER: &str = "rust_begin_unwind";

/// The tables of `docs/sections/firmware.md` between the `stack` markers:
/// one row per image, then one per cost-table row (`rows` as for
/// [`check_rows`]).
pub fn tables(
    images: &BTreeMap<&'static str, Analysed>,
    rows: &[(String, String, String)],
) -> Result<String> {
    let mut table = String::from(
        "| image | worst-case stack (bytes) | `main` | deepest handler + exception frame | without panic paths | custom joint (`&dyn`) called at | deepest path (frame bytes) |\n\
         |---|---:|---:|---:|---:|---:|---|\n",
    );
    for example in EXAMPLES {
        let analysed = &images[example.name];
        let image = image_bound(analysed, example.name)?;
        writeln!(
            table,
            "| `{}` | {} | {} | {} | {} | {} | {} |",
            example.name,
            image.total,
            image.thread.bytes,
            image.total - image.thread.bytes,
            image.total_without_panics,
            image.indirect_depth.map_or("-".into(), |d| d.to_string()),
            analysed
                .graph
                .short_path(&image.thread.path, &analysed.bounds),
        )?;
    }
    table.push_str(
        "\n| model | algorithm | painted (bytes) | worst case (bytes) | without panic paths | custom joint (`&dyn`) called at | deepest path (frame bytes) |\n\
         |---|---|---:|---:|---:|---:|---|\n",
    );
    for (model, algorithm, painted) in rows {
        if painted == "-" {
            continue;
        }
        let bound = row_bound(images, model, algorithm)?;
        writeln!(
            table,
            "| {model} | {algorithm} | {painted} | {} | {} | {} | {} |",
            bound.bytes,
            bound.without_panics,
            bound.indirect_depth.map_or("-".into(), |d| d.to_string()),
            bound.path
        )?;
    }
    table.push_str(
        "\nThe library's functions that the optimiser kept out of line, worst case from \
         their own entry in bytes (without panic paths in parentheses), the deepest of \
         their instances in each image:\n\n",
    );
    table.push_str(&algorithm_table(images));
    Ok(table)
}

/// The out-of-line functions of the library whose bounds the algorithm
/// table lists (path prefixes of the demangled names).
const ALGORITHM_PREFIXES: [&str; 3] = ["rodyn::algorithm::", "rodyn::drive::", "rodyn::sim::"];

/// One row per function of the library that the optimiser kept out of line
/// (`rodyn::algorithm`, `rodyn::drive`, `rodyn::sim`), one column per image:
/// its worst case from its own entry, the deepest of its instances (the
/// rest is inlined into its callers, whose rows are the cost table's).
pub fn algorithm_table(images: &BTreeMap<&'static str, Analysed>) -> String {
    let mut rows: BTreeMap<String, BTreeMap<&str, (u64, u64)>> = BTreeMap::new();
    for example in EXAMPLES {
        let analysed = &images[example.name];
        for (k, bound) in analysed.bounds.iter().enumerate() {
            let name = analysed.graph.name(k);
            let plain = without_generics(&name);
            if !ALGORITHM_PREFIXES.iter().any(|p| plain.starts_with(p)) {
                continue;
            }
            let short = plain.trim_start_matches("rodyn::").to_string();
            let cell = rows
                .entry(short)
                .or_default()
                .entry(example.name)
                .or_insert((0, 0));
            cell.0 = cell.0.max(bound.bytes);
            cell.1 = cell.1.max(analysed.without_panics[k].bytes);
        }
    }
    let mut table = String::from("| function |");
    for example in EXAMPLES {
        table.push_str(&format!(" `{}` |", example.name));
    }
    table.push_str("\n|---|");
    table.push_str(&"---:|".repeat(EXAMPLES.len()));
    table.push('\n');
    for (name, cells) in rows {
        table.push_str(&format!("| `{name}` |"));
        for example in EXAMPLES {
            match cells.get(example.name) {
                Some((bytes, without)) => table.push_str(&format!(" {bytes} ({without}) |")),
                None => table.push_str(" |"),
            }
        }
        table.push('\n');
    }
    table
}

/// A demangled name without its generic arguments (a qualified-self name,
/// `<A as T>::f`, keeps only `::f`, and no prefix of the table matches it).
fn without_generics(name: &str) -> String {
    let mut depth = 0;
    name.chars()
        .filter(|&c| {
            match c {
                '<' => depth += 1,
                '>' => depth -= 1,
                _ => return depth == 0,
            }
            false
        })
        .collect()
}

/// The worst case of every image (bytes), for the size table's RAM column.
pub fn image_totals(
    images: &BTreeMap<&'static str, Analysed>,
) -> Result<BTreeMap<&'static str, u64>> {
    images
        .iter()
        .map(|(name, a)| Ok((*name, image_bound(a, name)?.total)))
        .collect()
}

/// `<rodyn::joint::Joint<S> as …>::motion` → `Joint::motion`;
/// `rodyn::algorithm::aba::aba` → `aba::aba`.
fn last_segment(name: &str) -> String {
    let mut depth = 0;
    let plain: String = name
        .chars()
        .filter(|&c| {
            match c {
                '<' => depth += 1,
                '>' => depth -= 1,
                _ => return depth == 0,
            }
            false
        })
        .collect();
    let segments: Vec<&str> = plain.split("::").filter(|s| !s.is_empty()).collect();
    match segments.as_slice() {
        [] => name.to_string(),
        [one] => (*one).to_string(),
        [.., a, b] => format!("{a}::{b}"),
    }
}

/// The check of `cargo xtask test`: every image's cycles and stack moves,
/// and each row of the probes' fresh logs (written by the test's runs)
/// against its static bound.
pub fn check() -> Result<()> {
    let images = analyse()?;
    check_images(&images)?;
    let mut rows = Vec::new();
    for probe in crate::costs::PROBES {
        let log = firmware::last_log_path(firmware::example(probe)?);
        let text = std::fs::read_to_string(&log)
            .with_context(|| format!("reading {} (run the probe first)", log.display()))?;
        let lines: Vec<String> = text.lines().map(str::to_string).collect();
        rows.extend(crate::costs::stack_rows(&crate::costs::parse_costs(
            &lines,
        )?));
    }
    check_rows(&images, &rows)
}

/// The firmware's link arguments (`firmware/.cargo/config.toml`), which a
/// `RUSTFLAGS` of our own replaces.
const FIRMWARE_RUSTFLAGS: &str = "-C link-arg=-Tlink.x -C link-arg=-Tdefmt.x";

/// `cargo xtask stack --check-frames`: checks the frame reading against
/// LLVM's own figures. The firmware is built once more with
/// `-Z emit-stack-sizes` (accepted by stable rustc under
/// `RUSTC_BOOTSTRAP=1`), which records each function's frame in a
/// `.stack_sizes` section. That build goes to a target directory of its own
/// (`stack-sizes/` in the target directory), so that the images that are
/// measured, tabled and shipped are never built with an unstable flag and
/// their cost figures are untouched. Every function both readings know must
/// agree; a reading below LLVM's fails (the bounds would be unsound), one
/// above is reported (conservative).
fn check_frames() -> Result<()> {
    let dir = crate::shell::target_dir().join("stack-sizes");
    let mut command = crate::shell::cargo_command(&firmware::dir());
    command
        .args(["build", "--release", "--bins"])
        .env("CARGO_TARGET_DIR", &dir)
        .env("RUSTC_BOOTSTRAP", "1")
        .env(
            "RUSTFLAGS",
            format!("{FIRMWARE_RUSTFLAGS} -Z emit-stack-sizes"),
        );
    crate::shell::run(&mut command)?;
    let mut below = Vec::new();
    for example in EXAMPLES {
        let elf = dir.join(setup::TARGET).join("release").join(example.name);
        let graph = Graph::of_elf(&elf)?;
        let llvm = llvm_stack_sizes(&elf)?;
        let (mut agree, mut above, mut unknown) = (0, Vec::new(), 0);
        for f in &graph.functions {
            match llvm.get(&f.start) {
                Some(&size) if size == f.frame => agree += 1,
                Some(&size) if f.frame > size => {
                    above.push(format!("{} ({} > {size})", short_name(&f.name), f.frame));
                }
                Some(&size) => below.push(format!(
                    "{}: {} ({} < {size})",
                    example.name,
                    short_name(&f.name),
                    f.frame
                )),
                None => unknown += 1,
            }
        }
        println!(
            "{}: {agree} frames as LLVM's, {} above (conservative), {unknown} functions LLVM gives no figure for (compiler-builtins, assembly)",
            example.name,
            above.len()
        );
        for a in above {
            println!("  above: {a}");
        }
    }
    if !below.is_empty() {
        bail!("frames read below LLVM's figure: {}", below.join("; "));
    }
    Ok(())
}

/// LLVM's `.stack_sizes`: (function address, ULEB128 frame bytes) pairs.
fn llvm_stack_sizes(elf: &Path) -> Result<BTreeMap<u64, u64>> {
    let data = std::fs::read(elf)?;
    let file = object::File::parse(&*data)?;
    let section = file
        .section_by_name(".stack_sizes")
        .with_context(|| format!("no .stack_sizes section in {}", elf.display()))?;
    let bytes = section.data()?;
    let mut sizes = BTreeMap::new();
    let mut at = 0;
    while at + 4 <= bytes.len() {
        let address = u64::from(u32::from_le_bytes(bytes[at..at + 4].try_into()?)) & !1;
        at += 4;
        let (mut size, mut shift) = (0u64, 0);
        loop {
            let byte = *bytes.get(at).context("truncated .stack_sizes")?;
            at += 1;
            size |= u64::from(byte & 0x7f) << shift;
            shift += 7;
            if byte & 0x80 == 0 {
                break;
            }
        }
        sizes.insert(address, size);
    }
    Ok(sizes)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `a` calls `b`, which calls through a register, and tail-calls `c`,
    /// which calls `a` back: objdump's layout, with the padding after `b`
    /// that the symbol size cuts off.
    const LISTING: &str = "
prog:\tfile format elf32-littlearm

Disassembly of section .text:

00001000 <a>:
    1000:      \tpush\t{r4, r5, r6, r7, lr}
    1002:      \tsub\tsp, #0x10
    1004:      \tbl\t0x2000 <b>              @ imm = #0xff8
    1008:      \tcmp\tr0, #0x0
    100a:      \tit\tne
    100c:      \tpopne\t{r4, r5, r6, r7, pc}
    100e:      \tadd\tsp, #0x10
    1010:      \tpop.w\t{r4, r5, r6, r7, lr}
    1014:      \tb.w\t0x3000 <c>             @ imm = #0x1fe8

00002000 <b>:
    2000:      \tstr\tr11, [sp, #-4]!
    2004:      \tblx\tr3
    2006:      \tldr\tr11, [sp], #4
    200a:      \tbx\tlr
    200c:      \tbmi\t0x1000 <a>
    200e: 02 c8 84 bd  \t.word\t0xbd84c802

00003000 <c>:
    3000:      \tpush\t{r7, lr}
    3002:      \tvpush\t{d8, d9}
    3006:      \tbl\t0x1000 <a>
    300a:      \tvpop\t{d8, d9}
    300e:      \tpop\t{r7, pc}
    3010:      \tmov\tsp, r4
";

    fn graph() -> Graph {
        let sizes = HashMap::from([(0x2000, 0xc)]);
        Graph {
            functions: functions(LISTING, &sizes),
            entries: Vec::new(),
            debug_names: BTreeMap::new(),
            elf: Default::default(),
        }
    }

    #[test]
    fn frames_count_pushes_subtractions_and_write_back_stores() {
        let g = graph();
        let frames: Vec<u64> = g.functions.iter().map(|f| f.frame).collect();
        // a: 5 registers and 16 bytes; b: one register; c: 2 + 2 d-registers.
        assert_eq!(frames, [36, 4, 24]);
    }

    #[test]
    fn calls_charge_the_frame_and_tail_calls_the_depth_left() {
        let g = graph();
        let a = &g.functions[0];
        let edges: Vec<(usize, u64)> = a.calls.iter().map(|c| (c.target, c.depth)).collect();
        // The conditional `popne` gives nothing back; the tail call to `c`
        // comes after the epilogue.
        assert_eq!(edges, [(2, 0), (1, 36)]);
        // The padding after `b` (a `bmi` to `a`) is not read as a call.
        assert!(g.functions[1].calls.is_empty());
    }

    #[test]
    fn indirect_calls_are_kept_with_their_depth() {
        let g = graph();
        let b = &g.functions[1];
        assert_eq!(b.indirect.len(), 1);
        assert_eq!(b.indirect[0].depth, 4);
        let bounds = g.bounds();
        // From `a`: its frame, then `b`'s at the call.
        assert_eq!(bounds[0].indirect.as_ref().map(|(d, _)| *d), Some(40));
    }

    #[test]
    fn cycles_are_reported_and_followed_once() {
        let g = graph();
        let bounds = g.bounds();
        assert_eq!(bounds[0].bytes, 40); // a → b
        assert_eq!(bounds[2].bytes, 64); // c → a → b
        assert!(bounds[0].recursion.is_some());
        assert!(bounds[2].recursion.is_some());
        assert!(bounds[1].recursion.is_none());
    }

    #[test]
    fn an_unknown_move_of_sp_is_reported() {
        let g = graph();
        assert_eq!(g.unknown_sp(), ["c: 0x3010: mov sp, r4"]);
    }

    #[test]
    fn skipped_functions_are_not_entered() {
        let g = graph();
        let bounds = g.bounds_without(&[false, true, false]);
        // Without `b`: `a`'s own frame; `c` runs after `a`'s epilogue (24).
        assert_eq!(bounds[0].bytes, 36);
        assert_eq!(bounds[2].bytes, 24 + 36);
    }
}
