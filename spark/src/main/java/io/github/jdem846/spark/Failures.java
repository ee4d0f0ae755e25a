package io.github.jdem846.spark;

import java.io.IOException;
import java.io.UncheckedIOException;

/**
 * One line for a failed job: the message of the error that says what went wrong (an unreadable file, an unwritable
 * output), not Spark's wrapping of it or a stack trace.
 */
final class Failures {

    private static final String LOST_TASK = "most recent failure: ";

    private Failures() {
    }

    /** @return the innermost I/O or argument error's message, else the first line of the outermost one */
    static String oneLine(Throwable e) {
        for (Throwable t = e; t != null; t = t.getCause()) {
            if ((t instanceof IOException || t instanceof IllegalArgumentException) && t.getMessage() != null
                    && !(t instanceof UncheckedIOException)) {
                return firstLine(t.getMessage());
            }
        }
        String m = e.getMessage() == null ? e.toString() : e.getMessage();
        int lost = m.indexOf(LOST_TASK);
        if (lost >= 0) {
            // "… most recent failure: Lost task 0.3 in stage 1.0 (TID 7) (host executor 1): java.io.IOException: …"
            String rest = firstLine(m.substring(lost + LOST_TASK.length()));
            int colon = rest.indexOf("): ");
            rest = colon >= 0 ? rest.substring(colon + 3) : rest;
            int type = rest.indexOf(": ");
            return type >= 0 && rest.substring(0, type).matches("[\\w.$]+") ? rest.substring(type + 2) : rest;
        }
        return firstLine(m);
    }

    private static String firstLine(String s) {
        int nl = s.indexOf('\n');
        return (nl < 0 ? s : s.substring(0, nl)).strip();
    }
}
