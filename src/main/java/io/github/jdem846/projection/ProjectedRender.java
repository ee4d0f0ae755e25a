package io.github.jdem846.projection;

import io.github.jdem846.geo.LatLonBox;
import io.github.jdem846.job.JobListener;
import io.github.jdem846.job.ReliefJob;
import io.github.jdem846.job.ReliefResult;
import io.github.jdem846.output.WriteOptions;
import io.github.jdem846.output.WriteResult;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.render.RenderSettings;
import java.io.IOException;
import java.nio.file.Path;
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
     * Renders {@code job} (an RGBA product: relief or tint) and warps it.
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
     * before anything is read.
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
        WriteResult written = run(job, listener).write(file, options);
        written.notices().forEach(listener::notice);
        listener.phaseDone("write");
        return written;
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
            throw new IllegalArgumentException("only RGBA pictures (relief, tint) can be projected, not a gray "
                    + relief.job().product().name().toLowerCase(java.util.Locale.ROOT));
        }
        GridGeometry grid = relief.geometry();
        ProjectedExtent extent = ProjectedExtent.of(grid, projection);
        int[] size = width == 0 && height == 0 ? extent.pixels(relief.width(), 0) : extent.pixels(width, height);
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
