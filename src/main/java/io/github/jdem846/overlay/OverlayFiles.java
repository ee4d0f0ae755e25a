package io.github.jdem846.overlay;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.CrsResolver;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.apache.sis.referencing.CommonCRS;
import org.apache.sis.referencing.crs.AbstractCRS;
import org.apache.sis.referencing.cs.AxesConvention;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.io.ParseException;
import org.locationtech.jts.io.geojson.GeoJsonReader;
import org.opengis.referencing.crs.CoordinateReferenceSystem;

/**
 * Reads an overlay from a vector file, chosen by its extension: GeoJSON ({@code .geojson}, {@code .json}; a
 * FeatureCollection, a Feature or a bare geometry, longitude and latitude in degrees on WGS 84 as RFC 7946 says) or
 * an ESRI shapefile ({@code .shp}, its CRS from the {@code .prj} beside it; without one the coordinates are taken
 * to be in the picture's CRS). Attributes ({@code .dbf}, GeoJSON properties) are not read.
 */
public final class OverlayFiles {

    private static final long MAX_GEOJSON_BYTES = 512L << 20;

    private OverlayFiles() {
    }

    /**
     * @param file  a {@code .geojson}, {@code .json} or {@code .shp} file
     * @param style how to draw it
     * @return the overlay
     * @throws OverlayFileException when the file is missing, of another kind, or not readable as one
     */
    public static Overlay read(Path file, OverlayStyle style) throws OverlayFileException {
        String name = file.getFileName() == null ? file.toString()
                : file.getFileName().toString().toLowerCase(Locale.ROOT);
        if (!Files.isRegularFile(file)) {
            throw new OverlayFileException(file, Files.exists(file) ? "is not a file" : "no such file");
        }
        if (name.endsWith(".shp")) {
            return new Overlay(file.toString(), ShapefileGeometries.read(file), shapefileCrs(file),
                    style);
        }
        if (name.endsWith(".geojson") || name.endsWith(".json")) {
            return new Overlay(file.toString(), geoJson(file), crs84(), style);
        }
        throw new OverlayFileException(file, "unknown overlay file type; expected a .geojson, .json or .shp file");
    }

    /** @return WGS 84 with longitude first, the CRS of every RFC 7946 GeoJSON file */
    public static CoordinateReferenceSystem crs84() {
        return CommonCRS.WGS84.normalizedGeographic();
    }

    private static List<Geometry> geoJson(Path file) throws OverlayFileException {
        String text;
        try {
            if (Files.size(file) > MAX_GEOJSON_BYTES) {
                throw new OverlayFileException(file, "GeoJSON larger than 512 MiB is not read; split it");
            }
            text = Files.readString(file, StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            throw new OverlayFileException(file, "no such file");
        } catch (IOException e) {
            throw new OverlayFileException(file, "cannot be read as UTF-8 text (" + e.getMessage() + ")");
        }
        Geometry g;
        try {
            g = new GeoJsonReader(new GeometryFactory()).read(text);
        } catch (ParseException | RuntimeException e) {
            String why = e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage().strip();
            throw new OverlayFileException(file, "not valid GeoJSON (" + why.lines().findFirst().orElse("")
                    + "); expected a FeatureCollection, Feature or geometry object");
        }
        if (g == null) {
            throw new OverlayFileException(file, "not a GeoJSON FeatureCollection, Feature or geometry object");
        }
        List<Geometry> out = new ArrayList<>();
        for (int i = 0; i < g.getNumGeometries(); i++) {
            out.add(g.getGeometryN(i));
        }
        return out;
    }

    private static CoordinateReferenceSystem shapefileCrs(Path shp) throws OverlayFileException {
        String base = shp.getFileName().toString();
        Path prj = shp.resolveSibling(base.substring(0, base.length() - 4) + ".prj");
        if (!Files.isRegularFile(prj)) {
            prj = shp.resolveSibling(base.substring(0, base.length() - 4) + ".PRJ");
            if (!Files.isRegularFile(prj)) {
                return null;
            }
        }
        try {
            CrsInfo info = CrsResolver.complete(CrsResolver.fromWkt(Files.readString(prj, StandardCharsets.UTF_8)));
            CoordinateReferenceSystem crs = info.sis().orElseThrow(
                    () -> new IllegalArgumentException("Apache SIS could not make a CRS of it"));
            return AbstractCRS.castOrCopy(crs).forConvention(AxesConvention.RIGHT_HANDED);
        } catch (IOException e) {
            throw new OverlayFileException(prj, "cannot be read (" + e.getMessage() + ")");
        } catch (IllegalArgumentException e) {
            throw new OverlayFileException(prj, "not a CRS in WKT: " + e.getMessage());
        }
    }
}
