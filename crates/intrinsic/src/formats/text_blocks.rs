//! Large text outputs (portalgon JSON, Matrix Market) formatted in blocks on several threads and
//! written in order.
//!
//! A document is cut into blocks (a few thousand polygons, pairs or matrix rows each) whose text
//! depends on the block's index only; worker threads format the blocks (worker `w` takes blocks
//! `w`, `w + T`, `w + 2T`, ...) while the calling thread writes them to the output in index order.
//! The bytes are those of formatting the blocks one after the other, whatever the thread count
//! (determinism), and memory is bounded: each worker holds at most [`QUEUE`] formatted blocks
//! waiting to be written, plus the one it formats.

use std::io::{self, Write};
use std::sync::mpsc::{Receiver, SyncSender, sync_channel};

/// Formatted blocks a worker may have waiting for the writer.
const QUEUE: usize = 2;

/// The most formatting threads: the text of a block costs about as much to format as a fast
/// disk takes to take it, so more threads than this only queue up behind the writer.
const MAX_WORKERS: usize = 4;

/// The formatting threads used for `blocks` blocks: none (format on the calling thread) for a
/// single block or a single core.
fn workers(blocks: usize) -> usize {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    if blocks < 2 || cores < 2 {
        0
    } else {
        cores.min(MAX_WORKERS).min(blocks)
    }
}

/// Writes blocks `0..blocks` to `out` in order, `format(k, buf)` appending the text of block `k`
/// to an empty `buf`; `format` runs on worker threads (see the module doc). A panic in `format`
/// is propagated once the writer has stopped.
///
/// # Errors
/// The first error of `out`; the workers then stop after their current block.
pub(crate) fn write_blocks<W: Write + ?Sized>(
    out: &mut W,
    blocks: usize,
    format: impl Fn(usize, &mut Vec<u8>) + Sync,
) -> io::Result<()> {
    write_blocks_on(out, blocks, workers(blocks), format)
}

/// [`write_blocks`] on `workers` formatting threads (0: on the calling thread).
fn write_blocks_on<W: Write + ?Sized>(
    out: &mut W,
    blocks: usize,
    workers: usize,
    format: impl Fn(usize, &mut Vec<u8>) + Sync,
) -> io::Result<()> {
    if workers == 0 {
        let mut buf = Vec::new();
        for k in 0..blocks {
            buf.clear();
            format(k, &mut buf);
            out.write_all(&buf)?;
        }
        return Ok(());
    }
    std::thread::scope(|scope| {
        let mut queues = Vec::with_capacity(workers);
        for w in 0..workers {
            let (filled, to_write) = sync_channel::<Vec<u8>>(QUEUE);
            let (written, to_reuse) = sync_channel::<Vec<u8>>(QUEUE + 2);
            let format = &format;
            scope.spawn(move || format_blocks(w, workers, blocks, format, &filled, &to_reuse));
            queues.push((to_write, written));
        }
        write_in_order(out, blocks, queues)
    })
}

/// A worker: formats blocks `first, first + step, ...` into buffers (reused once written) and
/// queues them; stops when the writer has gone (an output error).
fn format_blocks(
    first: usize,
    step: usize,
    blocks: usize,
    format: &(impl Fn(usize, &mut Vec<u8>) + Sync),
    filled: &SyncSender<Vec<u8>>,
    to_reuse: &Receiver<Vec<u8>>,
) {
    // A new buffer is given the size of the largest block so far and a quarter, so that it
    // seldom grows (each growth copies it).
    let mut largest = 0;
    for k in (first..blocks).step_by(step) {
        let mut buf = to_reuse
            .try_recv()
            .unwrap_or_else(|_| Vec::with_capacity(largest + largest / 4));
        buf.clear();
        format(k, &mut buf);
        largest = largest.max(buf.len());
        if filled.send(buf).is_err() {
            return;
        }
    }
}

/// A worker's two queues as the writer holds them: its formatted blocks, and the buffers handed
/// back to it once written.
type Queues = (Receiver<Vec<u8>>, SyncSender<Vec<u8>>);

/// The writer: block `k` comes from worker `k % workers`. Returning drops the queues, which
/// stops the workers.
fn write_in_order<W: Write + ?Sized>(
    out: &mut W,
    blocks: usize,
    queues: Vec<Queues>,
) -> io::Result<()> {
    for k in 0..blocks {
        let (to_write, written) = &queues[k % queues.len()];
        // A worker gone before its last block has panicked: the scope propagates it.
        let Ok(buf) = to_write.recv() else {
            return Ok(());
        };
        out.write_all(&buf)?;
        // The worker may have enough buffers already; this one is then dropped.
        let _ = written.try_send(buf);
    }
    Ok(())
}

/// The number of blocks of `per_block` items holding `items` items.
pub(crate) fn block_count(items: usize, per_block: usize) -> usize {
    items.div_ceil(per_block)
}

/// The items of block `k` of `per_block` items among `items`.
pub(crate) fn block_range(k: usize, per_block: usize, items: usize) -> std::ops::Range<usize> {
    (k * per_block).min(items)..((k + 1) * per_block).min(items)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Block `k`: its index, repeated `k % 7` times, then a newline.
    fn text(k: usize, buf: &mut Vec<u8>) {
        for _ in 0..k % 7 {
            buf.extend_from_slice(k.to_string().as_bytes());
        }
        buf.push(b'\n');
    }

    #[test]
    fn blocks_are_written_in_order_whatever_the_threads() {
        for blocks in [0, 1, 2, 3, 10, 257] {
            let mut expected = Vec::new();
            let mut buf = Vec::new();
            for k in 0..blocks {
                buf.clear();
                text(k, &mut buf);
                expected.extend_from_slice(&buf);
            }
            for workers in 0..4 {
                let mut written = Vec::new();
                write_blocks_on(&mut written, blocks, workers, text).unwrap();
                assert_eq!(written, expected, "{blocks} blocks, {workers} workers");
            }
        }
    }

    /// Accepts `limit` bytes, then fails.
    struct Full {
        limit: usize,
        taken: usize,
    }

    impl Write for Full {
        fn write(&mut self, bytes: &[u8]) -> io::Result<usize> {
            if self.taken + bytes.len() > self.limit {
                return Err(io::Error::other("disk full"));
            }
            self.taken += bytes.len();
            Ok(bytes.len())
        }
        fn flush(&mut self) -> io::Result<()> {
            Ok(())
        }
    }

    #[test]
    fn an_output_error_stops_the_workers_and_is_returned() {
        for workers in 0..4 {
            let mut out = Full {
                limit: 100,
                taken: 0,
            };
            let e = write_blocks_on(&mut out, 10_000, workers, text).unwrap_err();
            assert_eq!(e.to_string(), "disk full");
            assert!(out.taken <= 100);
        }
    }

    #[test]
    fn ranges_cover_the_items() {
        assert_eq!(block_count(0, 4), 0);
        assert_eq!(block_count(9, 4), 3);
        assert_eq!(block_range(2, 4, 9), 8..9);
        assert_eq!(block_range(3, 4, 9), 9..9);
    }
}
