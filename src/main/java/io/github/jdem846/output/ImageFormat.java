package io.github.jdem846.output;

import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/** The image formats the renderer writes, chosen from the output file's extension (case-insensitive). */
enum ImageFormat {

    /** PNG: 8-bit RGBA or 8-bit gray; georeferencing only in sidecar files. */
    PNG("pgw", ".png"),
    /** GeoTIFF: single-band 8-bit gray or float32 (and 8-bit RGBA), georeferencing embedded. */
    GEOTIFF("tfw", ".tif", ".tiff"),
    /** JPEG: 8-bit RGB or gray, lossy, no transparency (RGBA pictures are laid on a background); sidecars only. */
    JPEG("jgw", ".jpg", ".jpeg");

    private final String worldFileExtension;
    private final List<String> extensions;

    ImageFormat(String worldFileExtension, String... extensions) {
        this.worldFileExtension = worldFileExtension;
        this.extensions = List.of(extensions);
    }

    /** @return the file extensions of this format, with the dot, lower case (the first is the preferred one) */
    public List<String> extensions() {
        return extensions;
    }

    /** @return the ESRI world-file extension of this format, without the dot: {@code pgw} or {@code tfw} */
    public String worldFileExtension() {
        return worldFileExtension;
    }

    /**
     * The format named by {@code file}'s extension.
     *
     * @throws IllegalArgumentException when the extension is missing or not supported; the message lists the
     *                                  supported extensions
     */
    public static ImageFormat of(Path file) {
        String name = file.getFileName() == null ? "" : file.getFileName().toString().toLowerCase(Locale.ROOT);
        for (ImageFormat format : values()) {
            for (String extension : format.extensions) {
                if (name.endsWith(extension) && name.length() > extension.length()) {
                    return format;
                }
            }
        }
        throw new IllegalArgumentException("cannot tell the image format of '" + file + "' from its extension; "
                + "supported: " + supportedExtensions());
    }

    /** @return all supported extensions, e.g. {@code ".png, .tif, .tiff"} */
    public static String supportedExtensions() {
        StringBuilder sb = new StringBuilder();
        for (ImageFormat format : values()) {
            for (String extension : format.extensions) {
                sb.append(sb.isEmpty() ? "" : ", ").append(extension);
            }
        }
        return sb.toString();
    }
}
