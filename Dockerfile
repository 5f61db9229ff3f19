# shadelab for screenshot tests in CI (docs/ci.md): the headless program (no viewer, no tests) built on
# Debian 12, packaged as a .deb and installed into a slim Debian 12 image.
#   docker build -t shadelab .
#   docker run --rm -v "$PWD:/work" shadelab --test screenshots --junit report.xml --report report.html
FROM debian:12 AS build
COPY third_party/install-deps.sh third_party/packages-headless.txt /src/third_party/
RUN bash /src/third_party/install-deps.sh /src/third_party/packages-headless.txt
COPY . /src
RUN cmake -S /src -B /build -G Ninja -DCMAKE_BUILD_TYPE=Release -DSHADELAB_VIEWER=OFF -DSHADELAB_BUILD_TESTS=OFF \
 && cmake --build /build \
 && cd /build && cpack -G DEB

FROM debian:12-slim
COPY --from=build /build/shadelab_*.deb /tmp/
# apt resolves the package's dependencies (OSMesa, the libraries it links, the font it recommends).
RUN apt-get update \
 && apt-get install -y --no-install-recommends /tmp/shadelab_*.deb fonts-dejavu-core \
 && rm -rf /var/lib/apt/lists/* /tmp/shadelab_*.deb
WORKDIR /work
ENTRYPOINT ["shadelab"]
CMD ["--help"]
