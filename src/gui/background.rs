//! Work off the GUI thread (issue 16, item 8): the one helper every file dialog, file
//! write, autosave and diagnosis job starts its thread with, so the GUI thread never
//! blocks. A thread's answer comes back over a channel, and the window repaints when it
//! arrives (an idle window sleeps until then).
//!
//! [`spawn`] is for work with one answer (a dialog, a write); [`spawn_stream`] for work
//! that reports as it goes (the diagnosis' progress, then its report). The simulation
//! thread ([`crate::gui::session::worker`]) is long-lived and has its own request queue.

use crossbeam_channel::{Receiver, Sender, TryRecvError, bounded, unbounded};

/// The answer of work started with [`spawn`], polled once a frame by whoever holds it.
pub struct Pending<T> {
    answer: Receiver<T>,
}

impl<T> std::fmt::Debug for Pending<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Pending")
    }
}

/// The thread ended without an answer (it panicked, or could not start).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Lost;

impl<T> Pending<T> {
    /// An answer already known (a thread that could not start, say).
    pub fn ready(value: T) -> Self {
        let (tx, answer) = bounded(1);
        let _ = tx.send(value);
        Self { answer }
    }

    /// `None` while the work runs; then its answer once, or [`Lost`].
    pub fn poll(&self) -> Option<Result<T, Lost>> {
        match self.answer.try_recv() {
            Ok(value) => Some(Ok(value)),
            Err(TryRecvError::Empty) => None,
            Err(TryRecvError::Disconnected) => Some(Err(Lost)),
        }
    }
}

/// Takes the answer out of `slot` once it has come (emptying the slot); `None` while the
/// work runs or when nothing is pending.
pub fn take<T>(slot: &mut Option<Pending<T>>) -> Option<Result<T, Lost>> {
    let answer = slot.as_ref()?.poll()?;
    *slot = None;
    Some(answer)
}

/// Runs `work` on a thread named `name`; the window repaints when it is done. The error
/// is for a person: the thread could not be started.
pub fn spawn<T: Send + 'static>(
    name: &str,
    ctx: &egui::Context,
    work: impl FnOnce() -> T + Send + 'static,
) -> Result<Pending<T>, String> {
    let (later, pending) = deferred();
    later
        .start(name, ctx, work)
        .map_err(|e| format!("cannot start a thread ({name}): {e}"))?;
    Ok(pending)
}

/// Work whose thread starts later than its answer is awaited: the PNG export's writing,
/// which can only start once the next frame's screenshot exists. Made by [`deferred`].
pub struct Deferred<T> {
    tx: Sender<T>,
}

/// A [`Deferred`] and the [`Pending`] its answer arrives on. If the `Deferred` is dropped
/// unstarted, the answer is [`Lost`].
pub fn deferred<T>() -> (Deferred<T>, Pending<T>) {
    let (tx, answer) = bounded(1);
    (Deferred { tx }, Pending { answer })
}

impl<T: Send + 'static> Deferred<T> {
    /// Runs `work` on a thread named `name` now; its answer goes to the [`Pending`]. A
    /// thread that cannot start leaves the answer [`Lost`].
    pub fn spawn(self, name: &str, ctx: &egui::Context, work: impl FnOnce() -> T + Send + 'static) {
        let _ = self.start(name, ctx, work);
    }

    /// The thread of [`Self::spawn`] and [`spawn`]: sends `work`'s answer, then repaints.
    fn start(
        self,
        name: &str,
        ctx: &egui::Context,
        work: impl FnOnce() -> T + Send + 'static,
    ) -> std::io::Result<()> {
        let (tx, ctx) = (self.tx, ctx.clone());
        std::thread::Builder::new()
            .name(name.into())
            .spawn(move || {
                let _ = tx.send(work());
                ctx.request_repaint();
            })
            .map(drop)
    }
}

/// Where streaming work sends its messages; every message repaints the window.
pub struct Sink<M> {
    tx: Sender<M>,
    ctx: egui::Context,
}

impl<M> Sink<M> {
    /// Sends `message` to the GUI thread (dropped if the window let the work go).
    pub fn send(&self, message: M) {
        let _ = self.tx.send(message);
        self.ctx.request_repaint();
    }
}

/// Runs `work` on a thread named `name`, handing it a [`Sink`] for its messages.
pub fn spawn_stream<M: Send + 'static>(
    name: &str,
    ctx: &egui::Context,
    work: impl FnOnce(Sink<M>) + Send + 'static,
) -> Result<Receiver<M>, String> {
    let (tx, messages) = unbounded();
    let sink = Sink {
        tx,
        ctx: ctx.clone(),
    };
    std::thread::Builder::new()
        .name(name.into())
        .spawn(move || work(sink))
        .map_err(|e| format!("cannot start a thread ({name}): {e}"))?;
    Ok(messages)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Polls `slot` with [`take`] until the answer comes (2 s at most).
    fn wait<T>(slot: &mut Option<Pending<T>>) -> Result<T, Lost> {
        for _ in 0..2000 {
            if let Some(answer) = take(slot) {
                assert!(slot.is_none(), "an answer taken empties its slot");
                return answer;
            }
            std::thread::sleep(std::time::Duration::from_millis(1));
        }
        panic!("no answer in 2 s");
    }

    #[test]
    fn answers_arrive_once_and_a_panicked_thread_is_lost() {
        let ctx = egui::Context::default();
        let mut slot = Some(spawn("test-answer", &ctx, || 42).expect("spawn"));
        assert_eq!(wait(&mut slot), Ok(42));
        assert_eq!(take(&mut slot), None, "nothing pending, nothing taken");

        // The thread's panic message is printed; its answer is Lost, not a hang.
        let mut lost: Option<Pending<u8>> =
            Some(spawn("test-panic", &ctx, || panic!("expected in this test")).expect("spawn"));
        assert_eq!(wait(&mut lost), Err(Lost));

        let mut ready = Some(Pending::ready("now"));
        assert_eq!(take(&mut ready), Some(Ok("now")));
    }

    #[test]
    fn a_stream_delivers_in_order() {
        let ctx = egui::Context::default();
        let rx = spawn_stream("test-stream", &ctx, |sink| {
            for k in 0..5 {
                sink.send(k);
            }
        })
        .expect("spawn");
        let got: Vec<i32> = rx.iter().collect();
        assert_eq!(got, vec![0, 1, 2, 3, 4]);
    }
}
