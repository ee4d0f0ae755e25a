package io.github.jdem846.cli;

import io.github.jdem846.job.JobListener;
import io.github.jdem846.sun.SunPosition;
import java.io.PrintWriter;
import java.util.Locale;

/**
 * What a job tells the command line: progress to the bar, notices and the sun computed to stderr as
 * {@code jdem846: …} lines, the end of each phase to the phase timer.
 */
final class ConsoleJobListener implements JobListener {

    private final ConsoleProgress progress;
    private final PrintWriter err;
    private final PhaseTimes times;
    private final String sunTime;

    /**
     * @param sunTime the {@code --sun-time} as given, named in the sun's line
     */
    ConsoleJobListener(ConsoleProgress progress, PrintWriter err, PhaseTimes times, String sunTime) {
        this.progress = progress;
        this.err = err;
        this.times = times;
        this.sunTime = sunTime;
    }

    @Override
    public void update(String stage, long done, long total) {
        progress.update(stage, done, total);
    }

    @Override
    public void notice(String message) {
        err.println("jdem846: note: " + message);
        err.flush();
    }

    @Override
    public void phaseDone(String phase) {
        times.lap(phase);
    }

    @Override
    public void sun(SunPosition sun) {
        err.println(String.format(Locale.ROOT, "jdem846: sun at %s: azimuth %.2f°, elevation %.2f°%s",
                sunTime, sun.azimuthDegrees(), sun.elevationDegrees(),
                sun.isBelowHorizon() ? " (below the horizon: no direct light)" : ""));
        err.flush();
    }
}
