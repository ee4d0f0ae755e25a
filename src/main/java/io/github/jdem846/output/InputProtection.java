package io.github.jdem846.output;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Locale;
import java.util.Objects;

/**
 * Refuses an output that would replace or delete an input: the image or one of its sidecars is the same file as
 * the DEM or one of the files read with it ({@code .hdr}, {@code .prj}, the members of a mosaic or VRT), or as a
 * sidecar that lies beside an input data file ({@link #sidecarsOf}: its {@code .prj}, {@code .hdr}, world file or
 * {@code .aux.xml}), however it is spelt ({@code x/../dem.tif}, a relative path, a symbolic link, a hard link: the
 * same file key). Done before any work, so that nothing is read or written in vain.
 */
public final class InputProtection {

    private InputProtection() {
    }

    /**
     * Checks that writing {@code image} with {@code options} ({@link ImageOutput#filesWritten}) touches none of
     * {@code inputFiles} (e.g. {@link io.github.jdem846.io.DemReader#filesOf}) nor their sidecars.
     *
     * @param image      the image to be written
     * @param options    how it will be written (its sidecars count too)
     * @param inputFiles the files the input is read from
     * @throws OutputOverwritesInputException naming the output file and the input it would destroy
     * @throws IOException                    when the file system cannot tell whether two files are the same
     */
    public static void check(Path image, WriteOptions options, Collection<Path> inputFiles) throws IOException {
        for (Path out : ImageOutput.filesWritten(image, options)) {
            checkOne(out, out.equals(image) ? null : image, inputFiles);
        }
    }

    /**
     * Checks that {@code output}, one file or archive to be written (a tile archive, say), is none of
     * {@code inputFiles} nor their sidecars.
     *
     * @param output     the file to be written
     * @param inputFiles the files the input is read from
     * @throws OutputOverwritesInputException naming both files
     * @throws IOException                    when the file system cannot tell whether two files are the same
     */
    public static void checkFile(Path output, Collection<Path> inputFiles) throws IOException {
        checkOne(output, null, inputFiles);
    }

    private static void checkOne(Path out, Path image, Collection<Path> inputFiles) throws IOException {
        if (!Files.exists(out)) {
            return;   // a file that does not exist yet cannot be an input
        }
        Objects.requireNonNull(inputFiles, "inputFiles");
        for (Path in : inputFiles) {
            if (Files.exists(in) && Files.isSameFile(out, in)) {
                throw new OutputOverwritesInputException(out, in, image, null);
            }
        }
        for (Path in : inputFiles) {
            for (Path sidecar : sidecarsOf(in)) {
                if (Files.exists(sidecar) && Files.isSameFile(out, sidecar)) {
                    throw new OutputOverwritesInputException(out, sidecar, image, in);
                }
            }
        }
    }

    /**
     * The names GIS software gives the sidecars of {@code file} ({@code dem.tif}): {@code dem.prj},
     * {@code dem.hdr}, the world files {@code dem.tfw}, {@code dem.tifw} and {@code dem.wld}, and
     * {@code dem.tif.aux.xml} and {@code dem.aux.xml}; whether or not they exist.
     *
     * @param file an input file
     * @return its possible sidecars
     */
    static List<Path> sidecarsOf(Path file) {
        Path name = file.getFileName();
        if (name == null) {
            return List.of();
        }
        String n = name.toString();
        int dot = n.lastIndexOf('.');
        String stem = dot > 0 ? n.substring(0, dot) : n;
        String ext = dot > 0 ? n.substring(dot + 1).toLowerCase(Locale.ROOT) : "";
        List<String> names = new ArrayList<>(List.of(stem + ".prj", stem + ".hdr", stem + ".wld", n + ".aux.xml",
                stem + ".aux.xml"));
        if (ext.length() >= 2) {
            names.add(stem + "." + ext.charAt(0) + ext.charAt(ext.length() - 1) + "w");
            names.add(stem + "." + ext + "w");
        }
        List<Path> sidecars = new ArrayList<>();
        for (String s : names) {
            if (!s.equals(n)) {
                sidecars.add(file.resolveSibling(s));
            }
        }
        return sidecars;
    }
}
