package io.github.jdem846.projection;

import io.github.jdem846.geo.LatLonBox;
import io.github.jdem846.job.JobListener;
import io.github.jdem846.job.Product;
import io.github.jdem846.job.ReliefJob;
import io.github.jdem846.job.ReliefResult;
import io.github.jdem846.output.GeoReference;
import io.github.jdem846.output.ImageOutput;
import io.github.jdem846.output.ImageSink;
import io.github.jdem846.output.WriteOptions;
import io.github.jdem846.output.WriteResult;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.render.RenderSettings;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Objects;

/**
 * A relief picture in a map projection: the {@link ReliefJob} renders on the DEM's own grid as ever (hillshade and
 * cast shadows measured in metres on that grid), then {@link PictureWarp} warps the picture into the projection,
 * over the projected bounding box of the DEM's area ({@link ProjectedExtent}).
 *
 * <pre>{@code
 * ProjectedPicture world = new ProjectedRender(MapProjection.named(ProjectionName.ROBINSON, 0), 1200, 0)
 *         .run(ReliefJob.of(Path.of("world.tif")), JobListener.NONE);
 * world.write(Path.of("world-robinson.png"), WriteOptions.defaults());
 * }</pre>
 *
 * @param projection the output's projection
 * @param width      output pixels across, or 0 to follow {@code height}
 * @param height     output pixels down, or 0 to follow {@code width}; both 0: as wide as the relief picture
 */
public record ProjectedRender(MapProjection projection, int width, int height) {

    /**
     * Checks that the projection is given and that the sizes are ≥ 0.
     *
     * @param projection the output's projection
     * @param width output pixels across, or 0 to follow {@code height}
     * @param height output pixels down, or 0 to follow {@code width}; both 0: as wide as the relief picture
     */
    public ProjectedRender {
        Objects.requireNonNull(projection, "projection");
        if (width < 0 || height < 0) {
            throw new IllegalArgumentException("a projected picture's size must be ≥ 0 (0 = from the other), got "
                    + width + " × " + height);
        }
    }

    /**
     * Renders {@code job} (an RGBA product: relief or tint; a gray one with {@link #runAndWrite} or {@link
     * #warpGray}) and warps it.
     *
     * @param job      the relief job, at the resolution the picture is to be shaded at
     * @param listener told of progress, notices and phases ("project" for the warp)
     * @return the projected picture
     * @throws IOException          when the DEM cannot be read
     * @throws InterruptedException when the calling thread is interrupted
     */
    public ProjectedPicture run(ReliefJob job, JobListener listener) throws IOException, InterruptedException {
        ReliefResult relief = job.run(listener);
        ProjectedPicture picture = warp(relief, job.execution());
        listener.phaseDone("project");
        return picture;
    }

    /**
     * Renders {@code job}, warps it and writes it; an output that would replace a file of the input is refused
     * before anything is read. Any product can be written: RGBA (relief, tint) or gray (hillshade, shadows, sky
     * view; see {@link #warpGray}). When the rendered picture and the projected one do not fit the job's {@linkplain
     * ReliefJob#memoryBudget() memory budget} together, the picture is rendered (in tiles, as {@link
     * ReliefJob#runAndWrite} does) to a temporary GeoTIFF next to {@code file}, then warped band of output rows by
     * band, each band reading only the rows of the picture it needs, and written band by band: the file is the
     * same, byte for byte.
     *
     * @param job      the relief job
     * @param file     the image file (PNG or GeoTIFF by its extension)
     * @param options  how to write it
     * @param listener told of progress, notices and phases
     * @return the files written
     * @throws IOException          when the DEM cannot be read or the file written
     * @throws InterruptedException when the calling thread is interrupted
     */
    public WriteResult runAndWrite(ReliefJob job, Path file, WriteOptions options, JobListener listener)
            throws IOException, InterruptedException {
        job.checkOutput(file, options);
        ReliefJob.Footprint footprint = job.footprint();
        boolean rgba = job.product() == Product.RELIEF || job.product() == Product.TINT;
        ProjectedExtent extent = ProjectedExtent.of(footprint.picture(), projection);
        int[] size = size(extent, footprint.picture().width());
        long projected = (long) size[0] * size[1] * (rgba ? 4 : 1);
        WriteResult written;
        if (footprint.fitsInMemory() && footprint.bytes() + projected <= job.memoryBudget()) {
            ReliefResult relief = job.run(listener);
            if (rgba) {
                ProjectedPicture picture = warp(relief, job.execution());
                listener.phaseDone("project");
                written = picture.write(file, options);
            } else {
                ProjectedGray picture = warpGray(relief, grayNoData(job.product(), options), job.execution());
                listener.phaseDone("project");
                written = picture.write(file, options);
            }
        } else {
            written = inBands(job, footprint.picture(), extent, size, rgba, file, options, listener);
        }
        written.notices().forEach(listener::notice);
        listener.phaseDone("write");
        return written;
    }

    /** Renders the picture to a temporary GeoTIFF, then warps and writes it band by band. */
    private WriteResult inBands(ReliefJob job, GridGeometry picture, ProjectedExtent extent, int[] size,
                                boolean rgba, Path file, WriteOptions options, JobListener listener)
            throws IOException, InterruptedException {
        Path dir = file.toAbsolutePath().getParent();
        Path temp = Files.createTempFile(dir, "." + file.getFileName() + "-", ".tif");
        try {
            job.runAndWrite(temp, WriteOptions.defaults().withoutNoData(), new Quiet(listener));
            Integer noData = grayNoData(job.product(), options);
            WriteOptions o = noData != null && options.noData() == null ? options.withNoData(noData) : options;
            GeoReference geo = new GeoReference(extent.west(), extent.north(), extent.east(), extent.south(),
                    projection.crsInfo());
            listener.notice(String.format(Locale.ROOT, "the projected %d×%d picture and its %d×%d source need more "
                    + "than the memory budget of %d MiB: warping it in bands", size[0], size[1], picture.width(),
                    picture.height(), job.memoryBudget() >> 20));
            try (TiffRows rows = TiffRows.open(temp, rgba);
                 ImageSink sink = rgba ? ImageOutput.openRgba(file, size[0], size[1], geo, o)
                         : ImageOutput.openGray(file, size[0], size[1], geo, o)) {
                PictureWarp.warpBands(rows, noData, picture, projection, extent, sink, job.memoryBudget(),
                        job.execution());
                listener.phaseDone("project");
                return sink.commit();
            }
        } finally {
            Files.deleteIfExists(temp);
        }
    }

    /** Passes on everything but the end of the "write" phase of the temporary picture. */
    private record Quiet(JobListener listener) implements JobListener {
        @Override
        public void update(String stage, long done, long total) {
            listener.update(stage, done, total);
        }

        @Override
        public void notice(String message) {
            listener.notice(message);
        }

        @Override
        public void phaseDone(String phase) {
            if (!"write".equals(phase)) {
                listener.phaseDone(phase);
            }
        }

        @Override
        public void sun(io.github.jdem846.sun.SunPosition position) {
            listener.sun(position);
        }
    }

    /** The no-data value a gray product is written with: 0 for a hillshade and a sky view (or as given), none for a shadow mask. */
    private static Integer grayNoData(Product product, WriteOptions options) {
        if (product != Product.HILLSHADE && product != Product.SKY_VIEW) {
            return product == Product.SHADOWS && options.noData() != null ? (int) Math.round(options.noData()) : null;
        }
        return options.noData() != null ? (int) Math.round(options.noData()) : 0;
    }

    private int[] size(ProjectedExtent extent, int reliefWidth) {
        return width == 0 && height == 0 ? extent.pixels(reliefWidth, 0) : extent.pixels(width, height);
    }

    /**
     * Warps a rendered gray picture (hillshade, shadow mask, sky view) by bilinear interpolation with its no-data
     * left out (as {@code gdalwarp -r bilinear -srcnodata}): 0 is no-data for a hillshade and a sky view, and
     * their pixels off the map or outside the DEM are 0; a shadow mask has no no-data, and its pixels off the map
     * are 0 (lit).
     *
     * @param gray      a gray picture
     * @param execution threads
     * @return the projected picture
     * @throws IllegalArgumentException when the picture is RGBA or its CRS unknown
     * @throws InterruptedException     when the calling thread is interrupted
     */
    public ProjectedGray warpGray(ReliefResult gray, RenderSettings execution) throws InterruptedException {
        return warpGray(gray, grayNoData(gray.job().product(), WriteOptions.defaults()), execution);
    }

    private ProjectedGray warpGray(ReliefResult gray, Integer noData, RenderSettings execution)
            throws InterruptedException {
        if (gray.gray() == null) {
            throw new IllegalArgumentException("an RGBA picture is warped with warp(), not warpGray()");
        }
        GridGeometry grid = gray.geometry();
        ProjectedExtent extent = ProjectedExtent.of(grid, projection);
        int[] size = size(extent, gray.width());
        byte[] out = PictureWarp.warpGray(gray.gray(), noData, grid, projection, extent, size[0], size[1], execution);
        return new ProjectedGray(projection, extent, size[0], size[1], out, noData);
    }

    /**
     * Warps a rendered picture.
     *
     * @param relief    an RGBA picture ({@link io.github.jdem846.job.Product#RELIEF} or {@code TINT})
     * @param execution threads
     * @return the projected picture
     * @throws IllegalArgumentException when the picture is gray or its CRS unknown
     * @throws InterruptedException     when the calling thread is interrupted
     */
    public ProjectedPicture warp(ReliefResult relief, RenderSettings execution) throws InterruptedException {
        if (relief.argb() == null) {
            throw new IllegalArgumentException("a gray " + relief.job().product().name().toLowerCase(Locale.ROOT)
                    + " is warped with warpGray(), not warp()");
        }
        GridGeometry grid = relief.geometry();
        ProjectedExtent extent = ProjectedExtent.of(grid, projection);
        int[] size = size(extent, relief.width());
        int[] argb = PictureWarp.warp(relief.argb(), grid, projection, extent, size[0], size[1], execution);
        return new ProjectedPicture(projection, extent, size[0], size[1], argb);
    }

    /**
     * The central meridian a named projection gets for an area by default: the area's central longitude for
     * transverse Mercator (to 0.001°); for the others 0°, unless the area crosses ±180°, then its central longitude.
     *
     * @param name the projection
     * @param area the DEM's longitude/latitude box
     * @return λ₀ in degrees, in [−180, 180]
     */
    public static double defaultCentralMeridian(ProjectionName name, LatLonBox area) {
        double centre = (area.west() + area.east()) / 2;
        centre = centre - 360 * Math.floor((centre + 180) / 360);
        centre = Math.rint(centre * 1000) / 1000;
        boolean crosses = area.west() < -180 || area.east() > 180;
        boolean world = area.east() - area.west() >= 359.999;
        return name == ProjectionName.TRANSVERSE_MERCATOR || (crosses && !world) ? centre : 0;
    }
}
