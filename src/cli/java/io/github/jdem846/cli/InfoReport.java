package io.github.jdem846.cli;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.LatLonBox;
import io.github.jdem846.io.DemInfo;
import io.github.jdem846.job.MercatorScale;
import io.github.jdem846.job.ScaleNotice;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import io.github.jdem846.sun.SunPosition;
import java.util.Locale;
import java.util.Optional;

/** What {@code jdem846 info} prints about a DEM, as text for a person or as one JSON object. */
final class InfoReport {

    private final DemInfo info;
    private final ElevationStatistics stats;
    private final GridGeometry g;
    private final Optional<LatLonBox> latLon;
    private final String sunTime;
    private final SunPosition sun;

    InfoReport(DemInfo info, ElevationStatistics stats) {
        this(info, stats, null, null);
    }

    /** With the sun at the DEM's centre at {@code sunTime} (both null for none). */
    InfoReport(DemInfo info, ElevationStatistics stats, String sunTime, SunPosition sun) {
        this.sunTime = sunTime;
        this.sun = sun;
        this.info = info;
        this.stats = stats;
        this.g = info.geometry();
        Optional<LatLonBox> box;
        try {
            box = g.latLonExtent();
        } catch (IllegalArgumentException e) {
            box = Optional.empty(); // outside the projection's domain
        }
        this.latLon = box;
    }

    /** The centre row, where {@code cellSizeMeters} is measured. */
    private int centerRow() {
        return g.height() / 2;
    }

    String toText() {
        CrsInfo crs = g.crs();
        StringBuilder sb = new StringBuilder();
        if (info.isMosaic()) {
            if (info.format() == io.github.jdem846.io.DemFormat.VRT) {
                line(sb, "File", info.source());
            }
            line(sb, "Format", info.format().displayName() + " of " + info.members().size()
                    + (info.members().size() == 1 ? " file" : " files") + " read as one grid");
            for (int i = 0; i < info.members().size(); i++) {
                line(sb, i == 0 ? "Files" : "", info.members().get(i).toString());
            }
        } else {
            line(sb, "File", info.source());
            line(sb, "Format", info.format().displayName());
        }
        line(sb, "Size", g.width() + " × " + g.height() + " cells" + (info.bands() > 1 ? ", " + info.bands()
                + " bands (band 1 read)" : ""));
        line(sb, "Data type", info.dataType().displayName());
        line(sb, "CRS", crsText(crs));
        String unit = switch (crs.kind()) {
            case GEOGRAPHIC -> "°";
            case PROJECTED -> crs.linearUnitMeters() == 1.0 ? " m" : " units of " + fmt(crs.linearUnitMeters())
                    + " m";
            case UNKNOWN -> " (unknown units)";
        };
        line(sb, "Extent", "west " + fmt(g.originX()) + ", east " + fmt(g.eastX()) + ", south " + fmt(g.southY())
                + ", north " + fmt(g.originY()) + unit.replace("units of", "in units of"));
        line(sb, "Extent lat/lon", latLon.map(b -> String.format(Locale.ROOT,
                "south %.6f°, north %.6f°, west %.6f°, east %.6f°", b.south(), b.north(), b.west(), b.east()))
                .orElse("unknown (" + (crs.kind() == CrsInfo.Kind.PROJECTED
                        ? "the projection is not known to Apache SIS offline" : "CRS unknown") + ")"));
        String metres = g.hasMetricUnits()
                ? String.format(Locale.ROOT, "%.3f × %.3f m at the centre row", g.cellWidthMeters(centerRow()),
                g.cellHeightMeters(centerRow()))
                : "size in metres unknown";
        if (g.hasMetricUnits() && crs.isGeographic()) {
            metres += String.format(Locale.ROOT, " (%.3f × %.3f m at the north row, %.3f × %.3f m at the south"
                    + " row)", g.cellWidthMeters(0), g.cellHeightMeters(0), g.cellWidthMeters(g.height() - 1),
                    g.cellHeightMeters(g.height() - 1));
        }
        line(sb, "Cell size", fmt(g.cellWidth()) + " × " + fmt(g.cellHeight()) + (crs.isGeographic() ? "°" : "")
                + "; " + metres);
        line(sb, "Anchor", g.declaredAnchor() == PixelAnchor.CENTER
                ? "cell centres (PixelIsPoint / xllcenter); extent shown to the outer cell edges"
                : "cell corners (PixelIsArea / xllcorner)");
        Double nd = info.declaredNoData();
        line(sb, "No-data", (nd == null ? "none declared" : Double.isNaN(nd) ? "NaN" : fmt(nd)) + " ("
                + stats.noDataCount() + " of " + stats.totalCount() + " cells)");
        line(sb, "Elevation", stats.isEmpty() ? "no valid cells" : "min " + fmt(stats.min()) + ", max "
                + fmt(stats.max()));
        if (sun != null) {
            line(sb, "Sun", String.format(Locale.ROOT, "azimuth %.4f°, elevation %.4f° (zenith %.4f°) at the "
                    + "centre at %s%s", sun.azimuthDegrees(), sun.elevationDegrees(), sun.zenithDegrees(), sunTime,
                    sun.isBelowHorizon() ? "; below the horizon" : ""));
        }
        for (String n : info.notices()) {
            line(sb, "Notice", n);
        }
        ScaleNotice.of(MercatorScale.GROUND.apply(g)).ifPresent(n -> line(sb, "Notice", n));
        return sb.toString().stripTrailing();
    }

    String toJson() {
        CrsInfo crs = g.crs();
        Double nd = info.declaredNoData();
        Json j = new Json()
                .string("file", info.source())
                .string("format", info.format().displayName())
                .strings("files", info.isMosaic() ? info.members().stream().map(Object::toString).toList()
                        : java.util.List.of(info.source()))
                .integer("width", (long) g.width())
                .integer("height", (long) g.height())
                .integer("bands", (long) info.bands())
                .string("dataType", info.dataType().displayName())
                .string("crs", crs.name())
                .integer("epsg", crs.epsg() == null ? null : (long) crs.epsg())
                .string("crsKind", crs.kind().name().toLowerCase(Locale.ROOT))
                .bool("crsAssumed", crs.assumed())
                .raw("nodata", nd == null ? "null" : Double.isNaN(nd) ? "\"NaN\"" : Json.number(nd))
                .integer("nodataCount", stats.noDataCount())
                .integer("validCount", stats.validCount())
                .number("min", stats.min())
                .number("max", stats.max())
                .raw("cellSize", new Json().number("x", g.cellWidth()).number("y", g.cellHeight()).toString())
                .raw("cellSizeMeters", g.hasMetricUnits() ? new Json().number("x", g.cellWidthMeters(centerRow()))
                        .number("y", g.cellHeightMeters(centerRow())).toString() : "null")
                .raw("extent", new Json().number("west", g.originX()).number("south", g.southY())
                        .number("east", g.eastX()).number("north", g.originY()).toString())
                .raw("extentLatLon", latLon.map(b -> new Json().number("south", b.south())
                        .number("north", b.north()).number("west", b.west()).number("east", b.east()).toString())
                        .orElse("null"))
                .string("anchor", g.declaredAnchor() == PixelAnchor.CENTER ? "center" : "corner")
                .raw("groundScaleFactor", g.groundScaleFactor().isPresent()
                        ? Json.number(g.groundScaleFactor().getAsDouble()) : "null")
                .strings("notices", info.notices());
        if (sun != null) {
            j.raw("sun", new Json().string("time", sunTime).number("azimuth", sun.azimuthDegrees())
                    .number("elevation", sun.elevationDegrees()).number("zenith", sun.zenithDegrees()).toString());
        }
        return j.toString();
    }

    private static String crsText(CrsInfo crs) {
        if (crs.kind() == CrsInfo.Kind.UNKNOWN && crs.name() == null && crs.epsg() == null) {
            return "unknown";
        }
        StringBuilder sb = new StringBuilder(crs.name() != null ? crs.name() : "unnamed");
        if (crs.epsg() != null) {
            sb.append(" (EPSG:").append(crs.epsg()).append(')');
        }
        switch (crs.kind()) {
            case GEOGRAPHIC -> sb.append(", geographic (degrees), ellipsoid ")
                    .append(crs.ellipsoid() != null ? crs.ellipsoid().name() : "unknown, WGS 84 used");
            case PROJECTED -> sb.append(", projected, unit ").append(fmt(crs.linearUnitMeters())).append(" m");
            case UNKNOWN -> sb.append(", units unknown");
        }
        if (crs.assumed()) {
            sb.append(" — ASSUMED, not stated by the file");
        }
        return sb.toString();
    }

    private static void line(StringBuilder sb, String label, String value) {
        sb.append(String.format(Locale.ROOT, "%-15s %s%n", label.isEmpty() ? "" : label + ":", value));
    }

    /** A number with up to 12 significant digits, without trailing zeros. */
    static String fmt(double v) {
        if (!Double.isFinite(v)) {
            return Double.toString(v);
        }
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        java.math.BigDecimal d = new java.math.BigDecimal(v).round(new java.math.MathContext(12))
                .stripTrailingZeros();
        // plain digits for map numbers; powers of ten for float32 sentinels such as -3.40282346639E+38
        return Math.abs(v) < 1e15 ? d.toPlainString() : d.toString();
    }
}
