//! A fake SPI device: an 18-bit absolute encoder on a simulated joint.

use crate::drivers::{encode_frame, COUNTS_PER_TURN, READ_POSITION};
use core::cell::Cell;
use core::convert::Infallible;
use core::f32::consts::PI;
use embedded_hal::spi::{ErrorType, Operation, SpiDevice};

/// The sensor end of [`AbsoluteEncoder`](crate::drivers::AbsoluteEncoder):
/// answers a [`READ_POSITION`] command with the joint angle, floored to a
/// whole count, plus the encoder's mounting offset.
#[derive(Debug)]
pub struct SimulatedEncoderSpi<'a> {
    angle: &'a Cell<f32>,
    mounting_offset: u32,
}

impl<'a> SimulatedEncoderSpi<'a> {
    /// An encoder reading `angle` (rad) whose zero is at `mounting_offset` counts.
    #[must_use]
    pub fn new(angle: &'a Cell<f32>, mounting_offset: u32) -> Self {
        Self {
            angle,
            mounting_offset,
        }
    }

    fn counts(&self) -> u32 {
        let turns = self.angle.get() * (COUNTS_PER_TURN as f32 / (2.0 * PI));
        // Floor (truncation rounds negative values up).
        let mut whole = turns as i32;
        if whole as f32 > turns {
            whole -= 1;
        }
        (whole + self.mounting_offset as i32).rem_euclid(COUNTS_PER_TURN as i32) as u32
    }
}

impl ErrorType for SimulatedEncoderSpi<'_> {
    type Error = Infallible;
}

impl SpiDevice for SimulatedEncoderSpi<'_> {
    fn transaction(&mut self, operations: &mut [Operation<'_, u8>]) -> Result<(), Infallible> {
        let mut commanded = false;
        for operation in operations {
            match operation {
                Operation::Write(bytes) => commanded = bytes.first() == Some(&READ_POSITION),
                Operation::Transfer(read, write) => {
                    commanded = write.first() == Some(&READ_POSITION);
                    read.fill(0);
                }
                Operation::TransferInPlace(bytes) => {
                    commanded = bytes.first() == Some(&READ_POSITION);
                    bytes.fill(0);
                }
                Operation::Read(buffer) => {
                    // Without a command the sensor's output stays idle-low.
                    let frame = if commanded {
                        encode_frame(self.counts(), false)
                    } else {
                        [0; 3]
                    };
                    for (out, byte) in buffer.iter_mut().zip(frame) {
                        *out = byte;
                    }
                    commanded = false;
                }
                Operation::DelayNs(_) => {}
            }
        }
        Ok(())
    }
}
