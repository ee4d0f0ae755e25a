package io.github.jdem846.cli;

import io.github.jdem846.render.RenderProgress;
import me.tongfei.progressbar.ProgressBar;
import me.tongfei.progressbar.ProgressBarBuilder;
import me.tongfei.progressbar.ProgressBarStyle;

/**
 * A progress bar on stderr (me.tongfei:progressbar) when stderr is a terminal; silent otherwise (pipes, CI, files).
 * One bar per stage.
 */
final class ConsoleProgress implements RenderProgress, AutoCloseable {

    private ProgressBar bar;
    private String stage;

    /** A progress reporter suited to the current console: a bar when interactive, nothing otherwise. */
    static ConsoleProgress create(boolean quiet) {
        return new ConsoleProgress(!quiet && System.console() != null);
    }

    private final boolean enabled;

    private ConsoleProgress(boolean enabled) {
        this.enabled = enabled;
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
                    .setStyle(ProgressBarStyle.ASCII).setConsumer(new me.tongfei.progressbar.ConsoleProgressBarConsumer(
                            System.err)).build();
        }
        bar.stepTo(done);
    }

    @Override
    public synchronized void close() {
        if (bar != null) {
            bar.close();
            bar = null;
        }
    }
}
