//! An 18-bit absolute rotary encoder read over SPI.
//!
//! The protocol is that of typical SSI/BiSS-style absolute joint encoders,
//! simplified: the controller writes the command byte [`READ_POSITION`] and
//! reads a 3-byte big-endian frame
//!
//! | bits   | meaning                                                    |
//! |--------|------------------------------------------------------------|
//! | 23..6  | position, 0 ..= 2¹⁸ - 1 counts per turn                    |
//! | 5..2   | zero                                                       |
//! | 1      | error flag (magnet lost, over-speed): 1 means do not trust |
//! | 0      | even parity over bits 23..1                                |
//!
//! One count is 2π / 2¹⁸ ≈ 24 µrad.

use core::f32::consts::PI;
use embedded_hal::spi::{Operation, SpiDevice};

/// Counts per revolution (18 bits).
pub const COUNTS_PER_TURN: u32 = 1 << 18;
/// The command that requests a position frame.
pub const READ_POSITION: u8 = 0xA6;
/// Length of a position frame in bytes.
pub const FRAME_BYTES: usize = 3;
const POSITION_SHIFT: u32 = 6;
const ERROR_BIT: u32 = 1 << 1;

/// Why a position could not be read.
#[derive(Clone, Copy, Debug, PartialEq, Eq, defmt::Format)]
pub enum EncoderError {
    /// The SPI transaction failed.
    Bus,
    /// The frame's parity does not match: corrupted on the wire.
    Parity,
    /// The encoder flagged its reading as invalid.
    Sensor,
}

/// An absolute encoder on an SPI bus (its own chip select).
#[derive(Debug)]
pub struct AbsoluteEncoder<SPI> {
    spi: SPI,
    zero_offset: u32,
}

impl<SPI: SpiDevice> AbsoluteEncoder<SPI> {
    /// An encoder whose reading `zero_offset` (counts) is the joint's zero.
    pub fn new(spi: SPI, zero_offset: u32) -> Self {
        Self {
            spi,
            zero_offset: zero_offset % COUNTS_PER_TURN,
        }
    }

    /// The joint angle in radians, in `[-π, π)`.
    ///
    /// # Errors
    /// A failed transaction, a parity error or the sensor's error flag.
    pub fn read_angle(&mut self) -> Result<f32, EncoderError> {
        let mut frame = [0u8; FRAME_BYTES];
        self.spi
            .transaction(&mut [
                Operation::Write(&[READ_POSITION]),
                Operation::Read(&mut frame),
            ])
            .map_err(|_| EncoderError::Bus)?;
        let counts = decode_frame(frame)?;
        let relative = (counts + COUNTS_PER_TURN - self.zero_offset) % COUNTS_PER_TURN;
        // Centre the turn on zero: counts above half a turn are negative angles.
        let signed = if relative >= COUNTS_PER_TURN / 2 {
            relative as i32 - COUNTS_PER_TURN as i32
        } else {
            relative as i32
        };
        Ok(signed as f32 * (2.0 * PI / COUNTS_PER_TURN as f32))
    }
}

/// The position in counts, after the frame's checks.
fn decode_frame(frame: [u8; FRAME_BYTES]) -> Result<u32, EncoderError> {
    let word = u32::from(frame[0]) << 16 | u32::from(frame[1]) << 8 | u32::from(frame[2]);
    if word.count_ones() % 2 != 0 {
        return Err(EncoderError::Parity);
    }
    if word & ERROR_BIT != 0 {
        return Err(EncoderError::Sensor);
    }
    Ok(word >> POSITION_SHIFT)
}

/// The frame an encoder sends for `counts` (the sensor side of the protocol).
#[must_use]
pub fn encode_frame(counts: u32, error: bool) -> [u8; FRAME_BYTES] {
    let mut word = (counts % COUNTS_PER_TURN) << POSITION_SHIFT;
    if error {
        word |= ERROR_BIT;
    }
    word |= word.count_ones() % 2;
    [(word >> 16) as u8, (word >> 8) as u8, word as u8]
}
