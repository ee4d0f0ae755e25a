package io.github.jdem846.output;

import io.github.jdem846.geo.CrsInfo;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * What a write of one image does besides the image: the sidecars due ({@link WriteOptions#sidecars()}) and their
 * texts (world file, {@code .prj}, GDAL {@code .aux.xml}), the notices for the user, and the sidecars of an earlier
 * run that would now be wrong and are removed after the image is in place.
 */
final class SidecarPlan {

    private final boolean due;
    private final boolean georeferenced;
    private final Path worldFile;
    private final Path prjFile;
    private final Path auxFile;
    private final String worldText;
    private final String prjText;
    private final String auxText;
    private final List<String> notices = new ArrayList<>();

    private SidecarPlan(Path file, ImageFormat format, GeoReference geo, int width, int height,
                        WriteOptions options) {
        this.due = isDue(format, options);
        this.georeferenced = geo != null;
        this.worldFile = due ? ImageOutput.worldFilePath(file, options.worldFileNaming()) : null;
        this.prjFile = due ? ImageOutput.prjPath(file) : null;
        this.auxFile = due ? ImageOutput.auxXmlPath(file) : null;
        String world = null;
        String prj = null;
        String aux = null;
        if (due && geo != null) {
            world = WorldFile.of(geo, width, height).toText();
            EsriPrj.Result esri = EsriPrj.of(geo.crs());
            if (esri.wkt().isPresent()) {
                prj = esri.wkt().get() + "\n";
                aux = GdalAuxXml.of(esri.wkt().get(), esri.crs());
            } else {
                notices.add(esri.notice());
            }
        }
        this.worldText = world;
        this.prjText = prj;
        this.auxText = aux;
        if (format == ImageFormat.GEOTIFF && geo != null) {
            geoTiffNotice(geo.crs()).ifPresent(notices::add);
        }
    }

    /**
     * The plan for writing {@code file}, after checking that the image and the sidecars to be written can be
     * written (before any encoding).
     *
     * @throws IOException naming the file that cannot be written
     */
    static SidecarPlan checked(Path file, ImageFormat format, GeoReference geo, int width, int height,
                               WriteOptions options) throws IOException {
        SidecarPlan plan = new SidecarPlan(file, format, geo, width, height, options);
        StagedFiles.checkWritable(file);
        for (Path sidecar : new Path[]{plan.worldText != null ? plan.worldFile : null,
                plan.prjText != null ? plan.prjFile : null, plan.auxText != null ? plan.auxFile : null}) {
            if (sidecar != null) {
                StagedFiles.checkWritable(sidecar);
            }
        }
        return plan;
    }

    /** Whether {@code options} ask for sidecars next to a file of {@code format}. */
    static boolean isDue(ImageFormat format, WriteOptions options) {
        return options.sidecars() == WriteOptions.Sidecars.ALWAYS
                || (options.sidecars() == WriteOptions.Sidecars.WHEN_NOT_EMBEDDED && format != ImageFormat.GEOTIFF);
    }

    /**
     * Stages the sidecars that can be written.
     *
     * @return them, in the order world file, {@code .prj}, {@code .aux.xml}
     */
    List<Path> stage(StagedFiles staged) throws IOException {
        List<Path> sidecars = new ArrayList<>();
        if (worldText != null) {
            staged.stageText(worldFile, worldText);
            sidecars.add(worldFile);
        }
        if (prjText != null) {
            staged.stageText(prjFile, prjText);
            staged.stageText(auxFile, auxText);
            sidecars.add(prjFile);
            sidecars.add(auxFile);
        }
        return sidecars;
    }

    /**
     * Once the image is in place: deletes the sidecars of an earlier run that this write could not replace.
     *
     * @return the notices of the whole write
     */
    List<String> removeStale() throws IOException {
        List<String> all = new ArrayList<>(notices);
        if (due) {
            String reason = georeferenced ? "the CRS is not known" : "the image has no georeferencing";
            if (worldText == null) {
                removeStale(worldFile, reason, all);
            }
            if (prjText == null) {
                removeStale(prjFile, reason, all);
                removeStale(auxFile, reason, all);
            }
        }
        return all;
    }

    private static void removeStale(Path sidecar, String reason, List<String> notices) throws IOException {
        if (Files.isRegularFile(sidecar)) {
            Files.delete(sidecar);
            notices.add("removed " + sidecar + " from an earlier run: " + reason);
        }
    }

    /** What a GeoTIFF reader will miss about {@code crs}, if anything. */
    private static Optional<String> geoTiffNotice(CrsInfo crs) {
        if (crs.kind() == CrsInfo.Kind.UNKNOWN) {
            return Optional.of("the GeoTIFF names no CRS: it is unknown");
        }
        if (crs.epsg() == null) {
            return Optional.of("the GeoTIFF records the CRS" + (crs.name() != null ? " '" + crs.name() + "'" : "")
                    + " without an EPSG code, so only its " + (crs.isGeographic() ? "ellipsoid" : "linear unit")
                    + " is known to readers; write sidecars (a .prj) for the full definition");
        }
        return Optional.empty();
    }
}
