package io.github.jdem846.job;

import io.github.jdem846.output.GeoReference;
import io.github.jdem846.output.ImageOutput;
import io.github.jdem846.output.ImageSink;
import io.github.jdem846.output.WriteOptions;
import io.github.jdem846.output.WriteResult;
import io.github.jdem846.overlay.Overlay;
import io.github.jdem846.overlay.OverlayPainter;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Objects;

/**
 * Runs a {@link ReliefJob} and writes its picture with vector overlays drawn on top ({@link OverlayPainter}). A
 * picture rendered in memory is drawn on whole; one rendered in tiles is drawn on band by band as the bands are
 * written, with the same pixels as the whole picture would get.
 *
 * @param job      the job; its product must be an RGBA picture (relief, tint or shadows drawn in colour)
 * @param overlays the overlays, drawn in this order
 */
public record OverlaidJob(ReliefJob job, List<Overlay> overlays) {

    /**
     * Checks the job and copies the list.
     *
     * @param job      the job; its product must be an RGBA picture (relief, tint or shadows drawn in colour)
     * @param overlays the overlays, drawn in this order
     */
    public OverlaidJob {
        Objects.requireNonNull(job, "job");
        overlays = List.copyOf(overlays);
    }

    /**
     * As {@link ReliefJob#runAndWrite(Path, WriteOptions, JobListener)}, with the overlays drawn.
     *
     * @param file     the image file (its extension chooses the format)
     * @param options  how to write it
     * @param listener told of progress, notices, the sun used and the end of each phase
     * @return the files written
     * @throws IOException               when the input cannot be read or the output cannot be written
     * @throws IllegalArgumentException  when an overlay cannot be placed in the picture's CRS, or the product is gray
     * @throws InterruptedException      when the calling thread is interrupted
     */
    public WriteResult runAndWrite(Path file, WriteOptions options, JobListener listener)
            throws IOException, InterruptedException {
        Objects.requireNonNull(file, "file");
        Objects.requireNonNull(options, "options");
        job.requireDrawable();
        job.checkOutput(file, options);
        return job.runAndWrite((picture, rgba) -> {
            OverlayPainter painter = painter(picture, rgba);
            ImageSink sink = ImageOutput.openRgba(file, picture.width(), picture.height(), GeoReference.of(picture),
                    options);
            return new PaintingSink(sink, painter);
        }, result -> {
            OverlayPainter painter = painter(result.geometry(), result.argb() != null);
            int[] argb = result.argb().clone();
            painter.paintRows(argb, 0, result.height());
            return new ReliefResult(result.job(), result.source(), result.geometry(), argb, null, result.sun())
                    .write(file, options, listener);
        }, listener);
    }

    private OverlayPainter painter(io.github.jdem846.raster.GridGeometry picture, boolean rgba) {
        if (!rgba) {
            throw new IllegalArgumentException("overlays are drawn on colour pictures only, not on a gray "
                    + job.product().name().toLowerCase(java.util.Locale.ROOT));
        }
        return OverlayPainter.of(overlays, picture);
    }

    /** Draws the overlays onto each band of rows before handing it on. */
    private static final class PaintingSink implements ImageSink {

        private final ImageSink sink;
        private final OverlayPainter painter;
        private int[] band = new int[0];

        PaintingSink(ImageSink sink, OverlayPainter painter) {
            this.sink = sink;
            this.painter = painter;
        }

        @Override
        public int width() {
            return sink.width();
        }

        @Override
        public int height() {
            return sink.height();
        }

        @Override
        public int rowsWritten() {
            return sink.rowsWritten();
        }

        @Override
        public void appendRgba(int[] argb, int rows) throws IOException {
            int n = sink.width() * rows;
            if (band.length < n) {
                band = new int[n];
            }
            System.arraycopy(argb, 0, band, 0, n);
            painter.paintRows(band, sink.rowsWritten(), rows);
            sink.appendRgba(band, rows);
        }

        @Override
        public void appendGray(byte[] gray, int rows) throws IOException {
            sink.appendGray(gray, rows);
        }

        @Override
        public WriteResult commit() throws IOException {
            return sink.commit();
        }

        @Override
        public void close() throws IOException {
            sink.close();
        }
    }
}
