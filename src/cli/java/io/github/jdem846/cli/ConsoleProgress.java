package io.github.jdem846.cli;

import io.github.jdem846.render.RenderProgress;
import java.io.PrintWriter;
import me.tongfei.progressbar.ConsoleProgressBarConsumer;
import me.tongfei.progressbar.DelegatingProgressBarConsumer;
import me.tongfei.progressbar.ProgressBar;
import me.tongfei.progressbar.ProgressBarBuilder;
import me.tongfei.progressbar.ProgressBarConsumer;
import me.tongfei.progressbar.ProgressBarStyle;

/**
 * A progress bar on stderr (me.tongfei:progressbar), one bar per stage (read, shadows, shading, write, …), each
 * named after its stage: redrawn in place when stderr is a terminal; silent otherwise (pipes, CI, files) unless
 * forced ({@code --progress}), when each redraw is a line of its own on the command's error stream, for logs.
 */
final class ConsoleProgress implements RenderProgress, AutoCloseable {

    /** Characters of a bar's line when it is not drawn on a terminal. */
    private static final int LOG_LINE_LENGTH = 100;

    private final boolean enabled;
    private final PrintWriter log;
    private ProgressBar bar;
    private String stage;

    private ConsoleProgress(boolean enabled, PrintWriter log) {
        this.enabled = enabled;
        this.log = log;
    }

    /**
     * A progress reporter: a bar when stderr is a terminal; when {@code forced}, a line per redraw on {@code err}
     * when it is not; nothing when {@code quiet}.
     *
     * @param quiet  no progress at all ({@code -q})
     * @param forced show progress even when stderr is not a terminal ({@code --progress})
     * @param err    where forced progress goes when stderr is not a terminal
     */
    static ConsoleProgress create(boolean quiet, boolean forced, PrintWriter err) {
        if (quiet) {
            return new ConsoleProgress(false, null);
        }
        if (onTerminal()) {
            return new ConsoleProgress(true, null);
        }
        return forced && err != null ? new ConsoleProgress(true, err) : new ConsoleProgress(false, null);
    }

    /**
     * True when the program runs on a terminal: a console exists and, from Java 22 on (where a console exists for
     * redirected streams too), {@code Console.isTerminal()} says so.
     */
    static boolean onTerminal() {
        java.io.Console console = System.console();
        if (console == null) {
            return false;
        }
        try {
            return (Boolean) java.io.Console.class.getMethod("isTerminal").invoke(console);
        } catch (ReflectiveOperationException beforeJava22) {
            return true;
        }
    }

    @Override
    public synchronized void update(String stageName, long done, long total) {
        if (!enabled) {
            return;
        }
        if (bar == null || !stageName.equals(stage)) {
            close();
            stage = stageName;
            bar = new ProgressBarBuilder().setTaskName(stageName).setInitialMax(total)
                    .setStyle(ProgressBarStyle.ASCII).setConsumer(consumer()).build();
        }
        bar.stepTo(done);
    }

    private ProgressBarConsumer consumer() {
        if (log == null) {
            return new ConsoleProgressBarConsumer(System.err);
        }
        String[] last = {null};
        return new DelegatingProgressBarConsumer(line -> {
            String text = line.stripTrailing();
            synchronized (log) {
                if (!text.equals(last[0])) {           // the bar redraws its last state when closed
                    last[0] = text;
                    log.println(text);
                    log.flush();
                }
            }
        }, LOG_LINE_LENGTH);
    }

    @Override
    public synchronized void close() {
        if (bar != null) {
            bar.close();
            bar = null;
        }
    }
}
