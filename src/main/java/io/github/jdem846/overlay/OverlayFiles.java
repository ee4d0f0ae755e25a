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
import java.util.Map;
import org.apache.sis.referencing.CommonCRS;
import org.apache.sis.referencing.crs.AbstractCRS;
import org.apache.sis.referencing.cs.AxesConvention;
import org.json.simple.JSONValue;
import org.json.simple.parser.JSONParser;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.io.ParseException;
import org.locationtech.jts.io.geojson.GeoJsonReader;
import org.opengis.referencing.crs.CoordinateReferenceSystem;

/**
 * Reads an overlay from a vector file, chosen by its extension: GeoJSON ({@code .geojson}, {@code .json}; a
 * FeatureCollection, a Feature or a bare geometry, longitude and latitude in degrees on WGS 84 as RFC 7946 says) or
 * an ESRI shapefile ({@code .shp}, its CRS from the {@code .prj} beside it; without one the coordinates are taken
 * to be in the picture's CRS). The simplestyle properties of a feature (GeoJSON {@code properties}, the fields of
 * a {@code .dbf} of the same names) style it over the file's style ({@link FeatureStyle}); other attributes are not
 * read.
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
            List<Geometry> records = ShapefileGeometries.read(file);
            List<FeatureStyle> recordStyles = DbfStyles.read(file, records.size());
            List<Geometry> geometries = new ArrayList<>();
            List<FeatureStyle> styles = new ArrayList<>();
            for (int i = 0; i < records.size(); i++) {
                if (records.get(i) != null) {
                    geometries.add(records.get(i));
                    styles.add(recordStyles.isEmpty() ? FeatureStyle.NONE : recordStyles.get(i));
                }
            }
            return new Overlay(file.toString(), geometries, shapefileCrs(file), style, styles);
        }
        if (name.endsWith(".geojson") || name.endsWith(".json")) {
            List<Geometry> geometries = new ArrayList<>();
            List<FeatureStyle> styles = new ArrayList<>();
            geoJson(file, geometries, styles);
            return new Overlay(file.toString(), geometries, crs84(), style, styles);
        }
        throw new OverlayFileException(file, "unknown overlay file type; expected a .geojson, .json or .shp file");
    }

    /** @return WGS 84 with longitude first, the CRS of every RFC 7946 GeoJSON file */
    public static CoordinateReferenceSystem crs84() {
        return CommonCRS.WGS84.normalizedGeographic();
    }

    private static void geoJson(Path file, List<Geometry> geometries, List<FeatureStyle> styles)
            throws OverlayFileException {
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
        Object root;
        try {
            root = new JSONParser().parse(text);
        } catch (org.json.simple.parser.ParseException | RuntimeException e) {
            String why = e instanceof org.json.simple.parser.ParseException p ? p.toString().strip() : firstLine(e);
            throw new OverlayFileException(file, "not valid GeoJSON (" + why
                    + "); expected a FeatureCollection, Feature or geometry object");
        }
        if (!(root instanceof Map<?, ?> object) || !(object.get("type") instanceof String)) {
            throw new OverlayFileException(file, "not a GeoJSON FeatureCollection, Feature or geometry object");
        }
        GeoJsonReader reader = new GeoJsonReader(new GeometryFactory());
        if ("FeatureCollection".equals(object.get("type"))) {
            if (!(object.get("features") instanceof List<?> features)) {
                throw new OverlayFileException(file, "a FeatureCollection without a \"features\" array");
            }
            for (int i = 0; i < features.size(); i++) {
                feature(file, "feature " + (i + 1), features.get(i), reader, geometries, styles);
            }
        } else if ("Feature".equals(object.get("type"))) {
            feature(file, "the feature", object, reader, geometries, styles);
        } else {
            add(file, "the geometry", object, reader, FeatureStyle.NONE, geometries, styles);
        }
    }

    private static void feature(Path file, String which, Object feature, GeoJsonReader reader,
                                List<Geometry> geometries, List<FeatureStyle> styles) throws OverlayFileException {
        if (!(feature instanceof Map<?, ?> f) || !"Feature".equals(f.get("type"))) {
            throw new OverlayFileException(file, which + " is not a GeoJSON Feature object");
        }
        FeatureStyle style;
        try {
            style = f.get("properties") instanceof Map<?, ?> p ? FeatureStyle.of(stringKeys(p)) : FeatureStyle.NONE;
        } catch (IllegalArgumentException e) {
            throw new OverlayFileException(file, which + ": " + e.getMessage());
        }
        if (f.get("geometry") instanceof Map<?, ?> g) {
            add(file, which, g, reader, style, geometries, styles);
        }
    }

    private static void add(Path file, String which, Map<?, ?> geometry, GeoJsonReader reader, FeatureStyle style,
                            List<Geometry> geometries, List<FeatureStyle> styles) throws OverlayFileException {
        Geometry g;
        try {
            g = reader.read(JSONValue.toJSONString(geometry));
        } catch (ParseException | RuntimeException e) {
            throw new OverlayFileException(file, which + ": not a valid GeoJSON geometry (" + firstLine(e) + ")");
        }
        if (g == null) {
            throw new OverlayFileException(file, which + ": not a GeoJSON geometry object");
        }
        for (int i = 0; i < g.getNumGeometries(); i++) {
            geometries.add(g.getGeometryN(i));
            styles.add(style);
        }
    }

    private static Map<String, Object> stringKeys(Map<?, ?> properties) {
        Map<String, Object> out = new java.util.LinkedHashMap<>();
        properties.forEach((k, v) -> out.put(String.valueOf(k), v));
        return out;
    }

    private static String firstLine(Exception e) {
        String why = e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage().strip();
        return why.lines().findFirst().orElse("");
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
