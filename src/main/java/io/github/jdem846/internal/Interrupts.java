package io.github.jdem846.internal;

import java.io.IOException;
import java.io.InterruptedIOException;
import java.net.SocketTimeoutException;
import java.nio.channels.ClosedByInterruptException;

/**
 * Tells an interrupt from a read or write failure. Interrupting a thread that is reading or writing a
 * {@link java.nio.channels.FileChannel} closes the channel and fails the operation with
 * {@link ClosedByInterruptException}, which a decoder may report as a corrupt file; a job that was interrupted
 * must end with {@link InterruptedException}, as its contract says, not with an I/O error about a file that is
 * fine.
 */
public final class Interrupts {

    private Interrupts() {
    }

    /**
     * Throws {@link InterruptedException} (interrupt status cleared) when the current thread was interrupted or
     * {@code e} comes from an interrupt; otherwise returns {@code e} for the caller to throw.
     *
     * @param e what a read or write threw
     * @return {@code e}, when it is a real I/O failure
     * @throws InterruptedException when it is an interrupt, with {@code e} as its cause
     */
    public static IOException interruptedOr(IOException e) throws InterruptedException {
        boolean interrupted = Thread.interrupted();
        for (Throwable t = e; t != null && !interrupted; t = t.getCause()) {
            interrupted = t instanceof ClosedByInterruptException
                    || t instanceof InterruptedIOException && !(t instanceof SocketTimeoutException);
        }
        if (interrupted) {
            InterruptedException stop = new InterruptedException("interrupted while reading or writing");
            stop.initCause(e);
            throw stop;
        }
        return e;
    }
}
