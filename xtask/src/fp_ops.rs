//! Floating-point arithmetic in a callgrind count: how many additions,
//! multiplications, divisions and square roots the executed instructions
//! performed, read from their mnemonics (`objdump -d`).
//!
//! This is the arithmetic a call needed, independent of how the compiler
//! moved the data around it: two libraries that compute the same result
//! are compared on it without trusting either one's source. A packed
//! instruction counts once per lane (`mulpd` on `xmm` registers is two
//! multiplications) and a fused multiply-add counts as a multiplication and
//! an addition. Moves, sign flips (`xorpd`), comparisons and conversions
//! are not arithmetic.

use anyhow::{bail, Context, Result};
use std::collections::HashMap;
use std::fmt;
use std::path::Path;
use std::process::Command;

/// Floating-point operations, by kind.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FpOps {
    /// Additions and subtractions.
    pub add: u64,
    /// Multiplications.
    pub mul: u64,
    /// Divisions.
    pub div: u64,
    /// Square roots, minima and maxima.
    pub other: u64,
}

impl FpOps {
    pub fn total(&self) -> u64 {
        self.add + self.mul + self.div + self.other
    }

    fn add_scaled(&mut self, ops: FpOps, times: u64) {
        self.add += ops.add * times;
        self.mul += ops.mul * times;
        self.div += ops.div * times;
        self.other += ops.other * times;
    }

    /// Per call, rounded.
    pub fn per_call(&self, calls: u64) -> FpOps {
        let per = |n: u64| (n + calls / 2) / calls;
        FpOps {
            add: per(self.add),
            mul: per(self.mul),
            div: per(self.div),
            other: per(self.other),
        }
    }
}

impl fmt::Display for FpOps {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} ({} add/sub, {} mul, {} div, {} sqrt/min/max)",
            self.total(),
            self.add,
            self.mul,
            self.div,
            self.other
        )
    }
}

/// The arithmetic of one instruction, from its mnemonic and operands as
/// objdump prints them (AT&T syntax).
pub fn classify(mnemonic: &str, operands: &str) -> FpOps {
    let base = mnemonic.strip_prefix('v').unwrap_or(mnemonic);
    // Fused multiply-adds: vfmadd231sd, vfnmsub132pd, ...
    let (fused, base) = match base
        .strip_prefix("fmadd")
        .or_else(|| base.strip_prefix("fmsub"))
        .or_else(|| base.strip_prefix("fnmadd"))
        .or_else(|| base.strip_prefix("fnmsub"))
    {
        Some(rest) => (true, rest.trim_start_matches(char::is_numeric)),
        None => (false, base),
    };
    let (op, suffix) = if fused {
        ("fma", base)
    } else {
        match ["add", "sub", "mul", "div", "sqrt", "min", "max"]
            .into_iter()
            .find(|op| base.starts_with(op))
        {
            Some(op) => (op, &base[op.len()..]),
            None => return FpOps::default(),
        }
    };
    let lanes = match suffix {
        "sd" | "ss" => 1,
        "pd" | "ps" => {
            let per_16_bytes = if suffix == "pd" { 2 } else { 4 };
            if operands.contains("%ymm") {
                2 * per_16_bytes
            } else if operands.contains("%zmm") {
                4 * per_16_bytes
            } else {
                per_16_bytes
            }
        }
        // addsubpd and friends are rare enough to leave out; integer
        // instructions (`add`, `addl`, `subq`, `mulx`) land here too.
        _ => return FpOps::default(),
    };
    let mut ops = FpOps::default();
    match op {
        "add" | "sub" => ops.add = lanes,
        "mul" => ops.mul = lanes,
        "div" => ops.div = lanes,
        "fma" => {
            ops.mul = lanes;
            ops.add = lanes;
        }
        _ => ops.other = lanes,
    }
    ops
}

/// The floating-point operations that `counts` (address → times executed,
/// per object file) performed.
pub fn count(counts: &HashMap<String, HashMap<u64, u64>>) -> Result<FpOps> {
    count_cached(counts, &mut HashMap::new())
}

/// [`count`], reusing the disassemblies in `cache` (object → arithmetic by
/// address) and adding the ones it makes.
pub fn count_cached(
    counts: &HashMap<String, HashMap<u64, u64>>,
    cache: &mut HashMap<String, HashMap<u64, FpOps>>,
) -> Result<FpOps> {
    let mut total = FpOps::default();
    for (object, addresses) in counts {
        if !cache.contains_key(object) {
            cache.insert(object.clone(), arithmetic(Path::new(object))?);
        }
        let arithmetic = &cache[object];
        for (address, times) in addresses {
            if let Some(ops) = arithmetic.get(address) {
                total.add_scaled(*ops, *times);
            }
        }
    }
    Ok(total)
}

/// The arithmetic instructions of an object file, by address.
pub fn arithmetic(object: &Path) -> Result<HashMap<u64, FpOps>> {
    let out = Command::new("objdump")
        .args(["-d", "--no-show-raw-insn", "-M", "att"])
        .arg(object)
        .output()
        .context("running objdump (binutils)")?;
    if !out.status.success() {
        bail!(
            "objdump failed on {}: {}",
            object.display(),
            String::from_utf8_lossy(&out.stderr).trim()
        );
    }
    let mut arithmetic = HashMap::new();
    for line in String::from_utf8_lossy(&out.stdout).lines() {
        // "   2f360:\tmulsd  %xmm1,%xmm0"
        let Some((address, instruction)) = line.trim_start().split_once(":\t") else {
            continue;
        };
        let Ok(address) = u64::from_str_radix(address, 16) else {
            continue;
        };
        let mut parts = instruction.split_whitespace();
        let Some(mnemonic) = parts.next() else {
            continue;
        };
        let operands = parts.next().unwrap_or("");
        let ops = classify(mnemonic, operands);
        if ops.total() > 0 {
            arithmetic.insert(address, ops);
        }
    }
    Ok(arithmetic)
}

#[cfg(test)]
mod tests {
    use super::{classify, FpOps};

    fn ops(add: u64, mul: u64, div: u64, other: u64) -> FpOps {
        FpOps {
            add,
            mul,
            div,
            other,
        }
    }

    #[test]
    fn counts_lanes_and_fused_operations() {
        assert_eq!(classify("mulsd", "%xmm1,%xmm0"), ops(0, 1, 0, 0));
        assert_eq!(classify("addpd", "%xmm1,%xmm0"), ops(2, 0, 0, 0));
        assert_eq!(classify("subps", "%xmm1,%xmm0"), ops(4, 0, 0, 0));
        assert_eq!(classify("vmulpd", "%ymm1,%ymm2,%ymm0"), ops(0, 4, 0, 0));
        assert_eq!(
            classify("vfmadd231sd", "%xmm2,%xmm1,%xmm0"),
            ops(1, 1, 0, 0)
        );
        assert_eq!(
            classify("vfnmsub132pd", "%xmm2,%xmm1,%xmm0"),
            ops(2, 2, 0, 0)
        );
        assert_eq!(classify("divsd", "%xmm1,%xmm0"), ops(0, 0, 1, 0));
        assert_eq!(classify("sqrtsd", "%xmm1,%xmm0"), ops(0, 0, 0, 1));
    }

    #[test]
    fn moves_and_integer_instructions_are_not_arithmetic() {
        for (mnemonic, operands) in [
            ("movsd", "%xmm1,%xmm0"),
            ("xorpd", "%xmm1,%xmm0"),
            ("ucomisd", "%xmm1,%xmm0"),
            ("add", "$0x8,%rsp"),
            ("addq", "$0x1,%rax"),
            ("subl", "%eax,%ecx"),
            ("mulx", "%rax,%rbx,%rcx"),
            ("cvtsi2sd", "%eax,%xmm0"),
        ] {
            assert_eq!(classify(mnemonic, operands), FpOps::default(), "{mnemonic}");
        }
    }
}
