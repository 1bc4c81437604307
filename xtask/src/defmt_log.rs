//! Decoding the firmware's defmt stream with the `defmt-decoder` library,
//! so no `defmt-print` needs to be installed.

use anyhow::{anyhow, Context, Result};
use defmt_decoder::{DecodeError, StreamDecoder, Table};

/// A decoder for the frames of one firmware image.
pub struct LogDecoder {
    table: Table,
}

impl LogDecoder {
    /// Reads the defmt table from the firmware's ELF.
    pub fn from_elf(elf: &[u8]) -> Result<Self> {
        let table = Table::parse(elf)
            .context("cannot read the defmt table")?
            .ok_or_else(|| anyhow!("the ELF holds no defmt table (is defmt linked?)"))?;
        Ok(Self { table })
    }

    /// A stream that turns raw bytes into log lines.
    pub fn stream(&self) -> LogStream<'_> {
        LogStream {
            decoder: self.table.new_stream_decoder(),
        }
    }
}

/// Incremental decoding of a byte stream.
pub struct LogStream<'t> {
    decoder: Box<dyn StreamDecoder + Send + Sync + 't>,
}

impl LogStream<'_> {
    /// Feeds `bytes` and calls `on_line` for every complete frame.
    pub fn feed(&mut self, bytes: &[u8], on_line: &mut dyn FnMut(String)) {
        self.decoder.received(bytes);
        loop {
            match self.decoder.decode() {
                Ok(frame) => {
                    let message = frame.display_message().to_string();
                    // println! frames have no level; logged frames are prefixed by it.
                    on_line(match frame.level() {
                        Some(level) => format!("{} {message}", level.as_str().to_uppercase()),
                        None => message,
                    });
                }
                Err(DecodeError::UnexpectedEof) => break,
                Err(DecodeError::Malformed) => on_line("(malformed defmt frame)".into()),
            }
        }
    }
}
